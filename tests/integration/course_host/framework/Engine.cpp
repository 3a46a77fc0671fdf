// Engine.cpp - the test host's engine: the course frame loop on a manual clock.
#include "Engine.h"
#include "ModelSettings.h"
#include "iContext.h"
#include "iDesign.h"

iEngine* CreateEngine(iContext* c) { return new Engine(c); }

Engine::Engine(iContext* c) : context(c), design(0), now(0), active(false) {
    // create the model components
    design = CreateDesign(context);
}

bool Engine::setup(int now) {
    this->now = now;
    design->initialize(now);
    active = true;
    return true;
}

int Engine::run(int frames, int msPerFrame) {
    int ran = 0;
    for (int i = 0; i < frames; ++i) {
        int rightNow = now + msPerFrame;
        if (!active || rightNow - now < MIN_ELAPSED_TIME) continue;
        now = rightNow;
        // update the model components
        design->update(now);
        ++ran;
    }
    return ran;
}

void Engine::suspend() {
    design->suspend();
    active = false;
}

void Engine::restore(int now) {
    this->now = now;
    design->restore(now);
    active = true;
}

void Engine::reset(int now) {
    this->now = now;
    design->reset(now);
}

// deletes the components in the reverse order of their creation
Engine::~Engine() {
    design->Delete();
}
