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

// What a step writes (the motion), and what it never does (the settings): a state whose settings are the last
// accepted ones needs only the first checked (checkMotion).
bool motionFinite(const RBDynamics& d) {
    const Vector* vectors[] = {&d.position,        &d.velocity,        &d.lastVelocity,  &d.temporalForce,
                               &d.angularVelocity, &d.angularMomentum, &d.temporalTorque};
    for (const Vector* v : vectors)
        if (!v->isFinite()) return false;
    return true;
}

bool settingsFinite(const RBDynamics& d) {
    return d.acceleration.isFinite() && d.force.isFinite() && d.com.isFinite() && d.torque.isFinite();
}

const wchar_t* checkKnownOrientation(RBDynamics& d, const Matrix* const* knownRotations) {
    const bool known =
        knownRotations && (d.orientation == *knownRotations[0] || d.orientation == *knownRotations[1]);
    return known ? nullptr : checkOrientation(d.orientation);
}

const wchar_t* const kNotFinite = L"a vector property is NaN or infinite";
} // namespace

const wchar_t* checkMotion(RBDynamics& d, const Matrix* const* knownRotations) {
    if (!motionFinite(d)) return kNotFinite;
    return checkKnownOrientation(d, knownRotations);
}

const wchar_t* checkDynamics(RBDynamics& d, const Matrix& knownInertia, const Matrix& knownInverse,
                             const Matrix* const* knownRotations) {
    if (!motionFinite(d) || !settingsFinite(d)) return kNotFinite;
    if (!validMass(d.mass)) return L"mass must be > 0 (or INFINITE_MASS)";
    if (!finite(d.dragCoefficient) || d.dragCoefficient < 0.0f)
        return L"dragCoefficient must be finite, >= 0";
    if (!finite(d.angularDrag) || d.angularDrag < 0.0f) return L"angularDrag must be finite, >= 0";
    // Outside these ranges a contact makes energy: restitution 50 sent a ball dropped from 2 m to 1,089 m,
    // friction -1 sped a box sliding at 2 m/s up to 21 m/s.
    if (!(d.restitution >= 0.0f && d.restitution <= 1.0f)) return L"restitution must be in [0, 1]";
    if (!(d.friction >= 0.0f && finite(d.friction))) return L"friction must be finite, >= 0";
    if (d.physicsType != PHYS_Falling && d.physicsType != PHYS_Floating && d.physicsType != PHYS_FixedInSpace)
        return L"physicsType is not a PhysicsType";
    if (const wchar_t* why = checkKnownOrientation(d, knownRotations)) return why;
    if (d.getInertiaTensor() != knownInertia || d.getInverseInertiaTensor() != knownInverse) {
        // Edited through the reference: accept the pair if both are valid and they are each other's inverse,
        // or if the inverse is zero (rotation locked) and the tensor finite.
        if (isRotationLock(d.getInverseInertiaTensor())) {
            if (!d.getInertiaTensor().isFinite()) return L"inertia tensor is not finite";
            return nullptr;
        }
        if (!isValidInertiaTensor(d.getInertiaTensor()))
            return L"inertia tensor is not finite, symmetric and positive definite";
        if (!isValidInertiaTensor(d.getInverseInertiaTensor()))
            return L"inverse inertia tensor is not zero, or finite, symmetric and positive definite";
        // In double: a product of two float tensors near the float limits stays finite.
        Eigen::Matrix3d product = gmath::block3(d.getInertiaTensor()).cast<double>() *
                                  gmath::block3(d.getInverseInertiaTensor()).cast<double>();
        if ((product - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-3)
            return L"inertia tensor and inverse inertia tensor disagree (use setInertiaTensor)";
    }
    return nullptr;
}

} // namespace physics
