// iLifetime.h - the second engine's way of taking a body out of a scene safely: kill(), isAlive(),
// resetAlive().
//
// kill() marks the body dead; its scene stops simulating it (it is skipped from the next step on) and removes
// it at the end of the current step, or of the next one when no step is running, so a callback may kill
// whatever it touches. The body itself stays valid until the game deletes it: a pointer held elsewhere (a
// spawner, a target list) never dangles and can ask isAlive(). A dead body added to a scene again is removed
// again at the end of the next step unless resetAlive() was called first (seed 000's rule), so a stale
// holder cannot revive a killed object by accident.
// remove() (iPhysicsScene, the seed-001 API) does not kill: a body removed and re-added simply simulates,
// as it always has. The body's collision geometry stays in its space until the game removes it there.
// Not part of iRigidBody (a game's own body need not implement it): bodies made by CreateRigidBody and
// CreatePhysicsFrame implement it, reached with lifetimeOf(body).
#pragma once

#include "iRigidBody.h"

class iLifetime {
public:
    virtual void kill() = 0;
    virtual bool isAlive() const = 0;
    virtual void resetAlive() = 0; // alive again; does not add the body to a scene

protected:
    ~iLifetime() = default; // part of a body: Delete() the body
};

// The lifetime of a body made by CreateRigidBody or CreatePhysicsFrame; nullptr for a game's own body.
inline iLifetime* lifetimeOf(iRigidBody* body) { return dynamic_cast<iLifetime*>(body); }
inline const iLifetime* lifetimeOf(const iRigidBody* body) { return dynamic_cast<const iLifetime*>(body); }
