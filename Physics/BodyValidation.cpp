// BodyValidation.cpp - the validity rules of a body's state (see RBDynamics.h, "Validation").
#include "BodyValidation.h"
#include "MathEigen.h"

#include <cmath>

namespace physics {

namespace {
bool finite(float f) { return std::isfinite(f); }
bool validMass(float m) { return m > 0.0f && !std::isnan(m) && (finite(m) || m == INFINITE_MASS); }

// The rotation part of an orientation: drift is cleaned, anything else is refused.
const wchar_t* checkOrientation(Matrix& o) {
    if (!o.isFinite()) return L"orientation is not finite";
    // Only the 3x3 block is a rotation; the homogeneous row and column carry nothing.
    o.m14 = o.m24 = o.m34 = 0.0f;
    o.m41 = o.m42 = o.m43 = 0.0f;
    o.m44 = 1.0f;
    if (isRotation(o, 1e-4f)) return nullptr;
    if (isRotation(o, 1e-2f)) { // float drift from composing rotations: clean it
        o = orthoNormalize(o);
        return nullptr;
    }
    return L"orientation is not a rotation (scaled, sheared or reflected)";
}
} // namespace

const wchar_t* checkDynamics(RBDynamics& d, const Matrix& knownInertia, const Matrix& knownInverse) {
    const Vector* vectors[] = {
        &d.position,       &d.velocity, &d.lastVelocity,    &d.acceleration, &d.force,
        &d.temporalForce,  &d.com,      &d.angularVelocity, &d.torque,       &d.temporalTorque,
        &d.angularMomentum};
    for (const Vector* v : vectors)
        if (!v->isFinite()) return L"a vector property is NaN or infinite";
    if (!validMass(d.mass)) return L"mass must be > 0 (or INFINITE_MASS)";
    if (!finite(d.dragCoefficient) || d.dragCoefficient < 0.0f)
        return L"dragCoefficient must be finite, >= 0";
    if (!finite(d.restitution) || !finite(d.friction)) return L"restitution or friction is not finite";
    if (d.physicsType != PHYS_Falling && d.physicsType != PHYS_Floating && d.physicsType != PHYS_FixedInSpace)
        return L"physicsType is not a PhysicsType";
    if (const wchar_t* why = checkOrientation(d.orientation)) return why;
    if (d.getInertiaTensor() != knownInertia || d.getInverseInertiaTensor() != knownInverse) {
        // Edited through the reference: accept the tensor if it is valid and its inverse matches it.
        if (!isValidInertiaTensor(d.getInertiaTensor()))
            return L"inertia tensor is not finite, symmetric and positive definite";
        gmath::Mat3 product =
            gmath::block3(d.getInertiaTensor()) * gmath::block3(d.getInverseInertiaTensor());
        if ((product - gmath::Mat3::Identity()).cwiseAbs().maxCoeff() > 1e-3f)
            return L"inertia tensor and inverse inertia tensor disagree (use setInertiaTensor)";
    }
    return nullptr;
}

} // namespace physics
