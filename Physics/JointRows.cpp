// JointRows.cpp - the joint blocks' work done out of line (JointRows.h): their effective masses, a 3x3
// inverse each, and the swinging point's solve. Out of the header because Eigen's inverse and products,
// instantiated in every file that includes it, cost about half a second of compile time a file (g++,
// syntax only: JointRows.h 2.55 -> 1.99 s; it reaches 29 of the simulator's files, most of them only for the
// layouts). Called once per joint a sub-step, beside a 3x3 inverse (the call's cost not measured apart).
#include "JointRowsInline.h"

namespace physics {

void PointBlock::setArms(const SolverBody& a, const SolverBody& b, const Vec3& armA, const Vec3& armB) {
    rA = armA;
    rB = armB;
    swings = false;
    const Mat3 sA = cross(rA), sB = cross(rB);
    const Mat3 k =
        (a.invMass + b.invMass) * Mat3::Identity() - sA * a.invInertia * sA - sB * b.invInertia * sB;
    mass = k.determinant() != 0 ? Mat3(k.inverse()) : Mat3::Zero();
}

void PointBlock::setSwingArms(const SolverBody& a, const SolverBody& b, bool lightIsB, const Vec3& arm,
                              const Vec3& swingArm, const Vec3& axis) {
    rA = lightIsB ? arm : Vec3(Vec3::Zero());
    rB = lightIsB ? Vec3(Vec3::Zero()) : arm;
    swings = true;
    swing = swingArm;
    swingAxis = axis;
    const SolverBody &heavy = lightIsB ? a : b, &light = lightIsB ? b : a;
    const Mat3 j = swing * axis.transpose() - cross(arm); // the heavy body's angular Jacobian
    const Mat3 d = (a.invMass + b.invMass) * Mat3::Identity() + j * heavy.invInertia * j.transpose();
    mass = d.determinant() != 0 ? Mat3(d.inverse()) : Mat3::Zero();
    swingScale = axis.dot(light.invInertia * axis);
    swingMass = mass * swing;
    swingDenominator = 1 + swingScale * swing.dot(swingMass);
    // The impulse carried over turns the light body as u now says: a u-part kept from poses before
    // would hold it by a force with no torque (a hinged pendulum kept its speed against gravity).
    swingImpulse = swing.dot(impulse);
    const Real along = swing.dot(d * swing), uu = swing.squaredNorm();
    swingCondition = along > 0 ? swingScale * uu * uu / along : 0;
}

// K^-1 r = y - D^-1 u (c u . y) / q and its u-part (u . y) / q, with y = D^-1 r and q = 1 + c u . D^-1 u
// (Sherman-Morrison; JointRows.h, PointBlock).
void PointBlock::solveSwing(SolverBody& a, SolverBody& b, const Vec3& bias, const JointSoftness& s) {
    const Vec3 y = mass * (speed(a, b) + swing * swingAxis.dot(b.w - a.w) + bias);
    const Real uy = swing.dot(y);
    const Vec3 change =
        -s.massScale * Vec3(y - swingMass * (swingScale * uy / swingDenominator)) - s.impulseScale * impulse;
    const Real swingChange = -s.massScale * (uy / swingDenominator) - s.impulseScale * swingImpulse;
    apply(a, b, change, swingChange);
    impulse += change;
    swingImpulse += swingChange;
}

void OrientationBlock::setMass(const SolverBody& a, const SolverBody& b) {
    const Mat3 k = a.invInertia + b.invInertia;
    mass = k.determinant() != 0 ? Mat3(k.inverse()) : Mat3::Zero();
}

} // namespace physics
