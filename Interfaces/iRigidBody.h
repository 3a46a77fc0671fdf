// iRigidBody.h - the interface to a rigid body: its RBDynamics, its drawn iFrame and its collision listeners.
//
// The simulator's RigidBody implements it (CreateRigidBody), and so does a game's own class in the
// collision-only route: a collision geometry reads position, com, orientation, velocity and physicsType from
// getDynamics(), which must therefore be current whenever populateContactList() runs, and the same object
// for the body's whole life (a space keeps the reference between calls while a geometry stays bound to the
// body, and reads it without asking the body again).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "RBDynamics.h"

class iFrame;
class iCollisionListener;

// The simulator's bodies (CreateRigidBody): restore/reset/suspend/release do nothing (a body has no device
// resources and its scene owns time). clone() copies the dynamics (unattached), listeners and force
// generators but not the frame binding (two bodies driving one frame would fight), and joins the same scene.
// Delete() removes the body from its scene; during a scene update (from a fixed updater, force generator or
// listener) the deletion is deferred to the end of the step and the frame is unbound at once.
class iRigidBody {
public:
    // initialization functions
    virtual iRigidBody* clone() const = 0;
    // Binds a frame whose T follows this body after every scene update (it is moved to the body at once);
    // nullptr unbinds. A frame bound at creation (CreateRigidBody(o)) instead gives the body its pose. The
    // body writes a rigid T (any scale in the frame is dropped); unbind or delete the body before deleting
    // the frame.
    virtual void attach(iFrame* o) = 0;
    virtual void attachListener(iCollisionListener* l) = 0;
    virtual void detachListener(const iCollisionListener* l) = 0;
    virtual void restore(int now) = 0;
    // execution functions
    virtual std::vector<iCollisionListener*>& getListeners() = 0;
    virtual iFrame* getFrame() = 0;
    virtual RBDynamics& getDynamics() = 0;
    virtual const RBDynamics& getDynamics() const = 0;
    virtual void setDynamics(const RBDynamics& d) = 0;
    // termination functions
    virtual void reset(int now) = 0;
    virtual void suspend() const = 0;
    virtual void release() const = 0;
    // Deletes this body and its RBDynamics; never the attached frame or the listeners.
    virtual void Delete() const = 0;

protected:
    // Not deleted through the interface: call Delete(). A game's own body class may have any destructor.
    ~iRigidBody() = default;
};

// Creates a body bound to frame o (may be nullptr) and adds it to the active physics scene; with no scene
// yet, error() says the body is not simulated (add() it to a scene later).
extern "C" iRigidBody* CreateRigidBody(iFrame* o);

// --- body lifetime: where the simulator and the collision detector meet ---
// Whoever destroys an iRigidBody calls rigidBodyDestroyed(rb) first (the simulator's bodies do it in their
// destructor; a collision-only game's own body class must do it too). Collision spaces watch for it and
// unbind every geometry bound to that body, so a geometry never reads a dead body's dynamics.
using RigidBodyWatcher = void (*)(const iRigidBody* dying, void* user);

namespace guardian_detail {
inline std::vector<std::pair<RigidBodyWatcher, void*>>& rigidBodyWatchers() {
    static std::vector<std::pair<RigidBodyWatcher, void*>> watchers;
    return watchers;
}
} // namespace guardian_detail

inline void watchRigidBodies(RigidBodyWatcher w, void* user) {
    guardian_detail::rigidBodyWatchers().emplace_back(w, user);
}
inline void unwatchRigidBodies(RigidBodyWatcher w, void* user) {
    auto& ws = guardian_detail::rigidBodyWatchers();
    ws.erase(std::remove(ws.begin(), ws.end(), std::make_pair(w, user)), ws.end());
}
inline void rigidBodyDestroyed(const iRigidBody* rb) {
    // A copy: a watcher may unwatch itself while being told.
    auto ws = guardian_detail::rigidBodyWatchers();
    for (auto& w : ws) w.first(rb, w.second);
}
