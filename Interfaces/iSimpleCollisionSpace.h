// iSimpleCollisionSpace.h - the all-pairs collision space: the reference every faster space is checked
// against.
//
// Surprise (as the seed says): there is no interface beyond iCollisionSpace, only the factory.
// samplesPerSecond sets how densely motion between two populateContactList calls is sampled.
#pragma once

#include <cstddef>

class iCollisionSpace;

extern "C" iCollisionSpace* CreateSimpleCollisionSpace(size_t samplesPerSecond = 60);
