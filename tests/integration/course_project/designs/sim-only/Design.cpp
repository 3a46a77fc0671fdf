// Design.cpp (sim-only project) - bodies fall and spin under forces; no collision code is present.
//
// Checks, from physics alone: a falling body's speed and drop agree with free fall (v = g t, and energy:
// drop = v^2 / 2g), a torqued body's spin grows as w = (torque / I) t, and the drawn objects follow.
#include "CourseDesign.h"
#include "MathDefinitions.h"
#include "iDesign.h"
#include "iObject.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iRigidBody.h"

#include <cmath>
#include <cstdio>

namespace {

int verdict = 1;
const float kG = 9.81f;
const float kStep = 1.0f / 60.0f; // the scene's default step
const int kFrames = 60;

bool check(bool ok, const char* what) {
    std::printf("  %s: %s\n", ok ? "ok  " : "FAIL", what);
    return ok;
}

class Design final : public iDesign {
public:
    void initialize(int now) override {
        m_start = now;
        m_faller = CreatePhysicsFrame();
        m_faller->getDynamics()->position = Vector(0, 100, 0);
        m_ball = CreateSphere(0.5f);
        m_ball->attachTo(m_faller);
        m_spinner = CreatePhysicsFrame();
        RBDynamics* s = m_spinner->getDynamics();
        s->physicsType = PHYS_Floating;
        s->setInertiaTensor(getSphereInertiaTensor(2.0f, 0.5f)); // I = 0.2 kg m^2
        s->torque = Vector(0, 1, 0);                             // alpha = 5 rad/s^2
    }
    void update(int now) override {
        m_now = now;
        if (++m_frames == kFrames) judge();
    }
    bool finished() const override { return m_frames >= kFrames; }
    void reset(int) override {}
    void restore(int) override {}
    void suspend() override {}
    void release() override {}
    void Delete() const override {
        m_ball->Delete();
        m_faller->Delete();
        m_spinner->Delete();
        delete this;
    }

private:
    void judge() {
        float elapsed = (m_now - m_start) / 1000.0f; // the scene lags this by at most a step or two
        const RBDynamics* f = m_faller->getDynamics();
        const RBDynamics* s = m_spinner->getDynamics();
        float v = -f->velocity.y, drop = 100.0f - f->position.y;
        std::printf("sim-only: %.3f s: fall v %.3f m/s drop %.3f m; spin w %.3f rad/s\n", elapsed, v, drop,
                    s->angularVelocity.y);
        bool ok = true;
        ok &= check(v <= kG * elapsed + 1e-3f && v >= kG * (elapsed - 2 * kStep), "fall speed = g t");
        ok &= check(std::fabs(drop - v * v / (2 * kG)) < 0.02f * drop + v * kStep, "drop = v^2 / 2g");
        ok &= check(std::fabs(f->velocity.x) + std::fabs(f->velocity.z) < 1e-6f, "no sideways drift");
        ok &= check(std::fabs(m_ball->position().y - f->position.y) <= v * kStep + 1e-3f,
                    "drawn object within one step of the body");
        float w = s->angularVelocity.y;
        ok &=
            check(w <= 5.0f * elapsed + 1e-3f && w >= 5.0f * (elapsed - 2 * kStep), "spin w = (torque/I) t");
        ok &= check(std::fabs(s->position.y) < 1e-6f, "floating body feels no gravity");
        verdict = ok ? 0 : 1;
    }

    iPhysicsFrame* m_faller = nullptr;
    iPhysicsFrame* m_spinner = nullptr;
    iObject* m_ball = nullptr;
    int m_start = 0, m_now = 0, m_frames = 0;
};

} // namespace

int courseVerdict() { return verdict; }

CourseSetup createCourseDesign(iContext* context) {
    // The course Engine creates the physics scene in its constructor; the engine here is handed it.
    iPhysicsScene* scene = CreatePhysicsScene(context);
    return {new Design(), scene, 600};
}
