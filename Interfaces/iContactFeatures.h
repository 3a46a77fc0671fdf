// iContactFeatures.h - which features of two shapes each contact joins, so a solver can match contacts
// from one call to the next (warm starting).
//
// Not part of the seed's iCollisionSpace (a game's own space need not implement it); the simple space
// does, reached with featuresOf(space). (The simulator's solver matches contacts by position and does not
// need it.)
#pragma once

#include "iCollisionSpace.h"

class iContactFeatures {
public:
    // One id per contact, parallel to getContactList(): the same pair of features touching on the next call
    // gives the same id (with the same g1, g2). nullptr when there are no contacts.
    virtual const unsigned* getContactFeatureIds() const = 0;

protected:
    ~iContactFeatures() = default; // part of a space: Delete() the space
};

// The feature ids of a space that provides them; nullptr for one that does not.
inline const iContactFeatures* featuresOf(const iCollisionSpace* space) {
    return dynamic_cast<const iContactFeatures*>(space);
}
