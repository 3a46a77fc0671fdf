// SceneProbe.h - for the joint scene tests: runs a built-in scene through the game's own runScene (the
// engine loop on its stepped 16 ms clock) and lets a test look at the scene's World at the start of every
// physics step, and helpers for what the tests measure (a joint's two anchors in world coordinates).
#pragma once

#include "GameTestSupport.h"

#include "iFixedUpdater.h"
#include "iJoint.h"
#include "iPhysicsFrame.h"
#include "iPhysicsSceneHooks.h"
#include "iPhysicsSceneSettings.h"

#include <functional>

namespace game_test {

// The scene "watched" builds the scene under test, then registers itself as a fixed updater: the game runs it
// like any scene, and look() sees its World at the start of each step (the state the last step left).
struct SceneProbe final : iFixedUpdater {
    const SceneSpec* spec = nullptr;
    World* world = nullptr;
    long steps = 0;
    std::function<void(const World&, long step)> look;
    void fixedUpdate(iPhysicsScene*, float) override {
        if (look) look(*world, steps);
        ++steps;
    }
};

inline SceneProbe& probe() {
    static SceneProbe p;
    return p;
}

// Runs the scene named name for frames frames as the game does, calling look at the start of every step;
// returns the game's status (RUN_OK: it held together) and its printed output in *text.
inline RunStatus runProbed(const std::string& name, int frames, std::function<void(const World&, long)> look,
                           std::string* text = nullptr) {
    static const bool registered = registerScene({"watched", "the scene under test, watched every step",
                                                  [](World& w) {
                                                      SceneProbe& p = probe();
                                                      p.spec->build(w);
                                                      p.world = &w;
                                                      hooksOf(w.scene())->addFixedUpdater(&p);
                                                  },
                                                  [](World& w, int frame) {
                                                      if (probe().spec->act) probe().spec->act(w, frame);
                                                  }});
    SceneProbe& p = probe();
    p.spec = findScene(name);
    if (!registered || !p.spec) return RUN_BAD_ARGUMENTS;
    p.steps = 0;
    p.look = std::move(look);
    GameOptions o;
    o.frames = frames;
    o.out = std::tmpfile();
    const RunStatus status = runScene(*findScene("watched"), o);
    if (text) *text = readBack(o.out);
    std::fclose(o.out);
    p.look = nullptr;
    p.world = nullptr; // deleted with the run
    return status;
}

inline float gravityOf(const World& w) { return -settingsOf(w.scene())->getGravity().y; }

// A point given in a body's own frame (nullptr: the world's), in world coordinates now.
inline Vector worldPoint(const iRigidBody* body, const Vector& local) {
    if (!body) return local;
    const RBDynamics& d = body->getDynamics();
    return d.getWorldOrigin() + local * d.getWorldOrientation();
}

// How far apart a joint's two anchors are now, m.
inline float anchorGap(const iJoint* j) {
    return length(worldPoint(j->getBodyA(), j->getLocalAnchorA()) -
                  worldPoint(j->getBodyB(), j->getLocalAnchorB()));
}

} // namespace game_test
