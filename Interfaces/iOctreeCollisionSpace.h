// iOctreeCollisionSpace.h - the collision space for many bodies, the seed's promised "octree" space: what is
// inside is a dynamic AABB tree of fat boxes (not a grid octree: it needs no world size and measured
// faster), whose candidate pairs persist between calls.
//
// It behaves exactly like the simple space (iSimpleCollisionSpace.h: same samplesPerSecond, same tests,
// filters, continuous sampling, events, contact budget, queries and shape cast); its contact list names the
// same pairs with the same contacts, listed planes first and then in the order the geometries joined the
// space (the simple space lists them by position along x). What differs is the cost: a geometry that stays
// inside its fat box (its bounds grown by 0.1 m and along its motion) costs a box compare per call, and
// only geometries that left theirs look for new pairs, so a call where little moved finds its pairs in
// time proportional to the pairs, not to the bodies sorted. Ray and overlap queries descend the tree
// (after a pose compare per geometry) instead of testing every geometry.
// Choose it for thousands of bodies, most of them resting or slow; the simple space for a few hundred.
#pragma once

#include <cstddef>

class iCollisionSpace;

extern "C" iCollisionSpace* CreateOctreeCollisionSpace(size_t samplesPerSecond = 60);
