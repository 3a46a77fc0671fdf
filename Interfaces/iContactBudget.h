// iContactBudget.h - the most contacts a collision space reports in one populateContactList call.
//
// Not part of the seed's iCollisionSpace (a game's own space need not implement it); the simple space does,
// reached with contactBudgetOf(space). Every reported contact costs memory downstream (the solver keeps
// about 2.4 KB per touching pair), and a pathological scene reports without bound: 10,000 spheres spawned at
// one point touch in 50 million pairs, two compounds of 3,000 children in 9 million contacts. With a budget,
// a call reports contacts in its usual order until the budget is reached and drops the rest (those pairs
// are neither reported nor told to listeners); the first call that drops any says so once with error().
// Dropped pairs are found again on later calls as the bodies that are reported move apart.
#pragma once

#include <cstddef>

#include "iCollisionSpace.h"

class iContactBudget {
public:
    static constexpr size_t kDefaultContactBudget = 200000; // about 500 MB of solver state at worst
    // At least 1; 0 is refused with error() (the budget is unchanged, false returned).
    virtual bool setContactBudget(size_t maxContacts) = 0;
    virtual size_t getContactBudget() const = 0;
    // Candidate pairs the last populateContactList call dropped (not tested, or tested after the budget
    // filled; a pair cut off part way counts too).
    virtual size_t getDroppedPairCount() const = 0;

protected:
    ~iContactBudget() = default; // part of a space: Delete() the space
};

// The budget of a space that has one (the simple space); nullptr for one that does not.
inline iContactBudget* contactBudgetOf(iCollisionSpace* space) {
    return dynamic_cast<iContactBudget*>(space);
}
inline const iContactBudget* contactBudgetOf(const iCollisionSpace* space) {
    return dynamic_cast<const iContactBudget*>(space);
}
