// iOctreeCollisionSpace.h - the collision space for many bodies, the seed's promised "octree" space. What is
// inside is not a grid octree but a dynamic AABB tree of fat boxes (a bounding-volume hierarchy: it needs no
// world size, and adapts to any spread of bodies) whose candidate pairs persist between calls.
//
// It behaves exactly like the simple space (iSimpleCollisionSpace.h: the same samplesPerSecond, tests,
// filters, continuous sampling, events, contact budget, queries and shape cast): its contact list names the
// same pairs with the same contacts, listed planes first and then in the order the geometries joined the
// space (the simple space lists them by position along x). Only the cost differs: a geometry that stays
// inside its fat box (its bounds grown by 0.1 m and stretched along its last motion) costs a box compare
// per call, and only geometries that left theirs look for new pairs, so finding pairs when little moved
// costs in proportion to the pairs. Ray and overlap queries descend the tree (after a pose compare per
// geometry) instead of testing every geometry.
// Measured (bench/collision BroadphaseBench.cpp, 10,000 boxes of 1 m): pair finding 15-20x faster than the
// simple space's sort-and-sweep when nothing moved, 2.5-4.5x when every box drifted 2 cm, and 0.6-0.9x
// (slower) when every box jumped 0.5 m; whole populateContactList calls 2.3-3.3x faster on a sparse scene,
// 1.05-1.25x on a dense one (where the exact pair tests dominate).
// Choose it for thousands of bodies, most of them resting or moving a little each step.
#pragma once

#include <cstddef>

class iCollisionSpace;

extern "C" iCollisionSpace* CreateOctreeCollisionSpace(size_t samplesPerSecond = 60);
