// BodyValidation.h - what makes an RBDynamics state valid, in one place (the scene checks every body before
// and after each step; setDynamics checks what it is handed).
#pragma once

#include "RBDynamics.h"

namespace physics {

// nullptr when d is valid, else what is wrong (for the error message). Orientation drift within 1e-2 of a
// rotation is cleaned in place with orthoNormalize (and a stray translation in the orientation's 4th row
// and column is cleared); further from a rotation is invalid. knownInertia is the inertia tensor last
// accepted: the expensive positive-definiteness check runs only when the tensor was changed through the
// non-const getInertiaTensor() reference. knownRotations (null, or two) are orientations known to be clean
// rotations (the last one accepted, the last one the engine wrote): an orientation equal to either is not
// checked again (the check was a tenth of a falling sphere's step).
const wchar_t* checkDynamics(RBDynamics& d, const Matrix& knownInertia, const Matrix& knownInverse,
                             const Matrix* const* knownRotations = nullptr);

// The part of checkDynamics for what a step writes: position, orientation, the velocities and momentum,
// the one-step force and torque (the settings - mass, material, constant forces, tensors - unchecked: for a
// state whose settings are, bit for bit, ones checkDynamics accepted).
const wchar_t* checkMotion(RBDynamics& d, const Matrix* const* knownRotations);

} // namespace physics
