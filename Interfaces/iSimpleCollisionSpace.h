// iSimpleCollisionSpace.h - the all-pairs collision space: the reference every faster space is checked
// against.
//
// Surprise (as the seed says): there is no interface beyond iCollisionSpace, only the factory.
// samplesPerSecond sets how densely motion between two populateContactList calls is sampled (0: never):
//  * every pair is tested at its current pose; pairs of two PHYS_FixedInSpace bodies (a bodiless plane counts
//    as fixed), geometries on the same body and geometry without a body are never tested;
//  * with delta > 0 (finite) and samplesPerSecond > 0, a pair not touching now whose relative motion since
//    the previous call exceeds a quarter of its smaller geometry's smallest dimension is checked along the
//    motion: a sphere exactly (swept against a sphere or box: it cannot pass through, at any speed; the
//    contact describes the first touch: pos on the other shape, depth = how far it went on past that
//    plane), anything else at max(ceil(delta * samplesPerSecond), motion / (half the smallest dimension))
//    interpolated poses (linear positions, slerped orientations), at most 64; the first touching sample is
//    reported. Planes are solid behind, so nothing passes through one.
// Cost: resting or slow pairs cost one exact test; a fast pair up to 64 (measured: 1,000 sparse bodies all
// moving fast cost about 1.4x a resting scene).
#pragma once

#include <cstddef>

class iCollisionSpace;

extern "C" iCollisionSpace* CreateSimpleCollisionSpace(size_t samplesPerSecond = 60);
