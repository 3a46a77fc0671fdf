// Design.cpp (sim+collision project) - the full loop: a ball falls under gravity onto a fixed floor box; the
// scene collides its bodies each step and the ball's listener hears the floor.
//
// Checks against physics: the first HitWall comes when the ball's bottom reaches the floor top (centre at
// y = 0.5, after a 9.5 m drop: within one step's travel), with a speed from energy conservation
// (v^2 = 2 g drop) and a normal pointing down at the floor.
#include "CourseDesign.h"
#include "MathDefinitions.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iDesign.h"
#include "iObject.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"

#include <cmath>
#include <cstdio>

namespace {

int verdict = 1;
const int kFrames = 120;
const float kG = 9.81f;

struct FirstHit final : iCollisionListener {
    iRigidBody* self = nullptr;
    iRigidBody* floor = nullptr;
    int hits = 0;
    float y = 0, speed = 0;
    Vector normal;
    void HitWall(iRigidBody* other, Vector n, Vector) override {
        if (other != floor || hits++) return;
        y = self->getDynamics().position.y;
        speed = -self->getDynamics().velocity.y;
        normal = n;
    }
};

bool check(bool ok, const char* what) {
    std::printf("  %s: %s\n", ok ? "ok  " : "FAIL", what);
    return ok;
}

class Design final : public iDesign {
public:
    explicit Design(iPhysicsScene* scene) : m_scene(scene) {}
    void initialize(int) override {
        m_space = CreateSimpleCollisionSpace();
        m_scene->setNewGlobalCollisionSpace(m_space); // set in setup, before any geometry is created
        m_ball = CreatePhysicsFrame();
        m_ball->getDynamics()->position = Vector(0, 10, 0);
        m_ballShape = CreateCSphere(m_ball->getRB(), 0.5f);
        m_floor = CreatePhysicsFrame();
        m_floor->getDynamics()->physicsType = PHYS_FixedInSpace;
        m_floor->getDynamics()->position = Vector(0, -0.5f, 0);
        m_floorShape = CreateCOBB(m_floor->getRB(), Vector(10, 0.5f, 10));
        m_listener.self = m_ball->getRB();
        m_listener.floor = m_floor->getRB();
        m_ball->getRB()->attachListener(&m_listener);
    }
    void update(int) override {
        if (++m_frames == kFrames) judge();
    }
    bool finished() const override { return m_frames >= kFrames; }
    void reset(int) override {}
    void restore(int) override {}
    void suspend() override {}
    void release() override {}
    void Delete() const override {
        m_ballShape->Delete();
        m_floorShape->Delete();
        m_ball->Delete();
        m_floor->Delete();
        m_scene->setNewGlobalCollisionSpace(nullptr);
        m_space->Delete();
        delete this;
    }

private:
    void judge() {
        float step = 1.0f / 60.0f;
        std::printf("sim+collision: first hit at y %.3f m, speed %.3f m/s (energy says %.3f), %d hits\n",
                    m_listener.y, m_listener.speed, std::sqrt(2 * kG * (10 - m_listener.y)), m_listener.hits);
        bool ok = true;
        ok &= check(m_listener.hits > 0, "the ball hit the floor");
        ok &= check(m_listener.y <= 0.5f + 1e-3f && m_listener.y >= 0.5f - m_listener.speed * step - 1e-3f,
                    "first hit when the ball's bottom reaches the floor (within one step)");
        float expected = std::sqrt(2 * kG * (10 - m_listener.y));
        ok &= check(std::fabs(m_listener.speed - expected) <= 0.02f * expected, "speed from v^2 = 2 g h");
        ok &= check(m_listener.normal.y < -0.999f, "normal points down, toward the floor");
        ok &= check(m_floor->getDynamics()->position.y == -0.5f, "the fixed floor never moved");
        verdict = ok ? 0 : 1;
    }

    iPhysicsScene* m_scene;
    iCollisionSpace* m_space = nullptr;
    iPhysicsFrame *m_ball = nullptr, *m_floor = nullptr;
    iCollisionGeometry *m_ballShape = nullptr, *m_floorShape = nullptr;
    FirstHit m_listener;
    int m_frames = 0;
};

} // namespace

int courseVerdict() { return verdict; }

CourseSetup createCourseDesign(iContext* context) {
    iPhysicsScene* scene = CreatePhysicsScene(context);
    return {new Design(scene), scene, 600};
}
