// Engine.cpp - the headless frame loop: physics first, then the design, each frame with the same `now`.
#include "iEngine.h"

#include "ModelSettings.h"
#include "iClock.h"
#include "iDesign.h"
#include "iPhysicsScene.h"

namespace {

class Engine final : public iEngine {
public:
    Engine(iContext* c, iDesign* d, iPhysicsScene* s, iClock* clock)
        : m_context(c), m_design(d), m_scene(s), m_clock(clock ? clock : CreateRealClock()) {
        m_now = m_lastFrame = m_clock->now();
    }
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    bool setup() override {
        if (!m_design) return false;
        m_now = m_lastFrame = m_clock->now();
        if (m_scene) m_scene->restore(m_now);
        m_design->initialize(m_now);
        return true;
    }

    bool step() override {
        m_clock->tick();
        int rightNow = m_clock->now();
        if (m_active && rightNow - m_lastFrame >= MIN_ELAPSED_TIME) {
            m_now = m_lastFrame = rightNow;
            // (a windowed engine would retrieve keyboard, mouse and joystick input here)
            if (m_scene) m_scene->update(rightNow);
            if (m_design) m_design->update(rightNow);
        }
        return !(m_design && m_design->finished());
    }

    int run(int frames) override {
        int done = 0;
        while (done < frames) {
            ++done;
            if (!step()) break;
        }
        return done;
    }

    void suspend() override {
        if (!m_active) return;
        m_active = false;
        if (m_scene) m_scene->suspend();
        if (m_design) m_design->suspend();
    }
    void restore() override {
        m_now = m_lastFrame = m_clock->now();
        if (m_scene) m_scene->restore(m_now);
        if (m_design) m_design->restore(m_now);
        m_active = true;
    }
    void reset() override {
        m_now = m_lastFrame = m_clock->now();
        if (m_scene) m_scene->reset(m_now);
        if (m_design) m_design->reset(m_now);
    }
    void release() override {
        if (m_scene) m_scene->release();
        if (m_design) m_design->release();
    }
    bool active() const override { return m_active; }
    int now() const override { return m_now; }
    iContext* context() const override { return m_context; }
    iPhysicsScene* physicsScene() const override { return m_scene; }

    void Delete() const override { delete this; }

private:
    ~Engine() {
        // Reverse order of creation: the design may still refer to bodies the scene owns.
        if (m_design) m_design->Delete();
        if (m_scene) m_scene->Delete();
        m_clock->Delete();
    }

    iContext* m_context;
    iDesign* m_design;
    iPhysicsScene* m_scene;
    iClock* m_clock;
    int m_now = 0;
    int m_lastFrame = 0;
    bool m_active = true;
};

} // namespace

extern "C" iEngine* CreateEngine(iContext* context, iDesign* design, iPhysicsScene* scene, iClock* clock) {
    return new Engine(context, design, scene, clock);
}
