// DefaultSpace.h - makes a space the default that new geometry joins, for one scope (the seed's order:
// space first, then geometry; a geometry made with no default space is reported with error()). The previous
// default comes back at the end of the scope.
#pragma once

#include "iCollisionSpace.h"

class DefaultSpace {
public:
    explicit DefaultSpace(iCollisionSpace* space) : m_previous(getDefaultCollisionSpace()) {
        setDefaultCollisionSpace(space);
    }
    ~DefaultSpace() { setDefaultCollisionSpace(m_previous); }
    DefaultSpace(const DefaultSpace&) = delete;
    DefaultSpace& operator=(const DefaultSpace&) = delete;

private:
    iCollisionSpace* m_previous;
};
