// FrameworkTest.cpp - the headless engine: course call order, stepped time, lifecycle, settings store.
#include "iClock.h"
#include "iContext.h"
#include "iDesign.h"
#include "iEngine.h"
#include "iObject.h"
#include "iPhysicsScene.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

std::vector<std::string>* journal = nullptr;
void log(const std::string& s) {
    if (journal) journal->push_back(s);
}

class RecordingScene final : public iPhysicsScene {
public:
    bool add(iRigidBody*) override { return true; }
    void setNewGlobalCollisionSpace(iCollisionSpace*) override {}
    void restore(int now) override { log("scene.restore " + std::to_string(now)); }
    void update(int now) override { log("scene.update " + std::to_string(now)); }
    void reset(int now) override { log("scene.reset " + std::to_string(now)); }
    void suspend() const override { log("scene.suspend"); }
    void release() const override { log("scene.release"); }
    void remove(const iRigidBody*) override {}
    void Delete() const override {
        log("scene.Delete");
        delete this;
    }
};

class RecordingDesign final : public iDesign {
public:
    explicit RecordingDesign(int stopAfter) : m_stopAfter(stopAfter) {}
    void initialize(int now) override { log("design.initialize " + std::to_string(now)); }
    void update(int now) override {
        ++m_updates;
        log("design.update " + std::to_string(now));
    }
    void reset(int now) override { log("design.reset " + std::to_string(now)); }
    void restore(int now) override { log("design.restore " + std::to_string(now)); }
    void suspend() override { log("design.suspend"); }
    void release() override { log("design.release"); }
    bool finished() const override { return m_stopAfter > 0 && m_updates >= m_stopAfter; }
    void Delete() const override {
        log("design.Delete");
        delete this;
    }

private:
    int m_stopAfter;
    int m_updates = 0;
};

} // namespace

TEST(Engine, PhysicsUpdatesBeforeDesignWithTheSameSteppedNow) {
    std::vector<std::string> calls;
    journal = &calls;
    iEngine* engine =
        CreateEngine(nullptr, new RecordingDesign(0), new RecordingScene, CreateSteppedClock(16));
    ASSERT_TRUE(engine->setup());
    EXPECT_EQ(engine->run(3), 3);
    engine->Delete();
    journal = nullptr;
    std::vector<std::string> expected = {
        "scene.restore 0",  "design.initialize 0", "scene.update 16",  "design.update 16", "scene.update 32",
        "design.update 32", "scene.update 48",     "design.update 48", "design.Delete",    "scene.Delete"};
    EXPECT_EQ(calls, expected);
}

TEST(Engine, SuspendedFramesUpdateNothingAndRestorePassesNow) {
    std::vector<std::string> calls;
    journal = &calls;
    iEngine* engine =
        CreateEngine(nullptr, new RecordingDesign(0), new RecordingScene, CreateSteppedClock(10));
    engine->setup();
    engine->step();
    engine->suspend();
    engine->run(5); // time passes (50 ms), nothing updates
    engine->restore();
    engine->step();
    engine->Delete();
    journal = nullptr;
    std::vector<std::string> expected = {"scene.restore 0",  "design.initialize 0", "scene.update 10",
                                         "design.update 10", "scene.suspend",       "design.suspend",
                                         "scene.restore 60", "design.restore 60",   "scene.update 70",
                                         "design.update 70", "design.Delete",       "scene.Delete"};
    EXPECT_EQ(calls, expected);
}

TEST(Engine, RunStopsWhenTheDesignFinishesAndWorksWithoutAScene) {
    iEngine* engine = CreateEngine(nullptr, new RecordingDesign(4), nullptr, CreateSteppedClock(16));
    engine->setup();
    EXPECT_EQ(engine->run(100), 4);
    EXPECT_EQ(engine->now(), 64);
    engine->Delete();
}

TEST(Clock, SteppedClockIsDeterministicAndRealClockMovesForward) {
    iClock* a = CreateSteppedClock(7, 100);
    for (int i = 0; i < 3; ++i) a->tick();
    EXPECT_EQ(a->now(), 121);
    a->Delete();
    iClock* real = CreateRealClock();
    int t0 = real->now();
    EXPECT_GE(t0, 0);
    EXPECT_GE(real->now(), t0); // monotonic
    real->Delete();
}

TEST(Context, UnsetKeysReadAsZeroAndSetKeysReadBack) {
    iContext* c = CreateContext();
    EXPECT_FALSE(c->isSet(GF_FRAMES));
    EXPECT_EQ(c->get(GF_FRAMES), 0);
    c->set(GF_FRAMES, 120);
    c->set(GF_GRAVITY, Vector(0, -1.62f, 0));
    EXPECT_TRUE(c->isSet(GF_FRAMES));
    EXPECT_EQ(c->get(GF_FRAMES), 120);
    EXPECT_EQ(c->get(GF_GRAVITY).y, -1.62f);
    c->set(static_cast<Integer>(-1), 5); // out of range: ignored, no crash
    EXPECT_EQ(c->get(static_cast<Integer>(GF_NO_INTEGERS)), 0);
    c->Delete();
}

TEST(Object, AnObjectAttachedToAFrameFollowsIt) {
    iObject* o = CreateBox(-1, -1, -1, 1, 1, 1);
    iFrame* f = CreateFrame();
    o->attachTo(f);
    f->translate(0, 5, 0);
    EXPECT_NEAR(o->position().y, 5.0f, 1e-6f);
    EXPECT_EQ(o->maximum().x, 1.0f);
    o->Delete(); // the child first, as the seed's sample does
    f->Delete();
}
