// TimedScene.h - a physics scene with a World, built by a function and stepped one fixed 60 Hz step at a time
// with its wall time: the benchmarks that step two variants of one scene alternately (so that contention on a
// shared machine hits both alike) build each one of these.
#pragma once

#include "World.h"
#include "iPhysicsScene.h"

#include <chrono>
#include <cmath>
#include <functional>

struct TimedScene {
    using Build = std::function<void(World&)>;
    iPhysicsScene* scene;
    World* world;
    explicit TimedScene(const Build& build) {
        scene = CreatePhysicsScene(nullptr);
        scene->update(0);
        world = new World(scene);
        build(*world);
    }
    ~TimedScene() {
        delete world;
        scene->Delete();
    }
    TimedScene(const TimedScene&) = delete;
    TimedScene& operator=(const TimedScene&) = delete;
    // Fixed step i (1-based, engine time rounded up past it); returns its wall time in seconds.
    double step(int i) {
        auto t0 = std::chrono::steady_clock::now();
        scene->update(int(std::ceil(i * 1000.0 / 60.0)));
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
};
