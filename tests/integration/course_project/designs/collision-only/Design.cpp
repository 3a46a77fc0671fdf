// Design.cpp (collision-only project) - the student's own iRigidBody moves two balls through each other;
// the collision space reports their contacts and calls HitWall on both sides.
//
// Checks against geometry: the balls (radius 0.5, 10 m apart, closing at 4 m/s) first touch when their
// centres are 1 m apart, i.e. at t = 2.25 s; while they overlap the contact depth is 1 - distance, the normal
// points from g1 to g2, and each side's HitWall normal points toward the other ball.
#include "CourseDesign.h"
#include "MathDefinitions.h"
#include "iCOBB.h"
#include "iCSphere.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iDesign.h"
#include "iFrame.h"
#include "iObject.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

int verdict = 1;
const int kFrames = 200;

// The student's body: it moves itself (no simulator) and keeps getDynamics() current, as the seed asks.
class Ball final : public iRigidBody {
public:
    Ball(iFrame* frame, const Vector& at, const Vector& velocity) : m_frame(frame) {
        m_d.position = at;
        m_d.velocity = velocity;
        m_d.physicsType = PHYS_Floating;
        sync();
    }
    ~Ball() { rigidBodyDestroyed(this); }
    void move(float dt) {
        m_d.position += m_d.velocity * dt;
        sync();
    }
    iRigidBody* clone() const override { return new Ball(nullptr, m_d.position, m_d.velocity); }
    void attach(iFrame* f) override { m_frame = f; }
    void attachListener(iCollisionListener* l) override { m_listeners.push_back(l); }
    void detachListener(const iCollisionListener* l) override {
        m_listeners.erase(std::remove(m_listeners.begin(), m_listeners.end(), l), m_listeners.end());
    }
    void restore(int) override {}
    std::vector<iCollisionListener*>& getListeners() override { return m_listeners; }
    iFrame* getFrame() override { return m_frame; }
    RBDynamics& getDynamics() override { return m_d; }
    const RBDynamics& getDynamics() const override { return m_d; }
    void setDynamics(const RBDynamics& d) override { m_d = d; }
    void reset(int) override {}
    void suspend() const override {}
    void release() const override {}
    void Delete() const override { delete this; }

private:
    void sync() {
        if (!m_frame) return;
        Vector move = m_d.position - m_frame->position(); // a root frame: T's translation is world space
        m_frame->translate(move.x, move.y, move.z);
    }
    RBDynamics m_d;
    iFrame* m_frame;
    std::vector<iCollisionListener*> m_listeners;
};

struct HitCounter final : iCollisionListener {
    iRigidBody* self = nullptr;
    int hits = 0;
    bool normalsTowardOther = true;
    void HitWall(iRigidBody* other, Vector n, Vector) override {
        ++hits;
        Vector toOther = other->getDynamics().position - self->getDynamics().position;
        if (dot(n, toOther) <= 0.0f || std::fabs(n.length() - 1.0f) > 1e-4f) normalsTowardOther = false;
    }
};

bool check(bool ok, const char* what) {
    std::printf("  %s: %s\n", ok ? "ok  " : "FAIL", what);
    return ok;
}

class Design final : public iDesign {
public:
    void initialize(int now) override {
        m_last = now;
        m_space = CreateSimpleCollisionSpace();
        setDefaultCollisionSpace(m_space); // geometries created from now on join it
        for (int i = 0; i < 2; ++i) {
            m_objects[i] = CreateSphere(0.5f);
            float side = i == 0 ? -1.0f : 1.0f;
            m_balls[i] = new Ball(m_objects[i], Vector(5 * side, 1, 0), Vector(-2 * side, 0, 0));
            m_geoms[i] = CreateCSphere(m_balls[i], 0.5f);
            m_counters[i].self = m_balls[i];
            m_balls[i]->attachListener(&m_counters[i]);
        }
    }
    void update(int now) override {
        float dt = (now - m_last) / 1000.0f;
        m_last = now;
        m_time += dt;
        for (Ball* b : m_balls) b->move(dt);
        m_space->populateContactList(dt);
        float distance = (m_balls[1]->getDynamics().position - m_balls[0]->getDynamics().position).length();
        bool passed = m_balls[0]->getDynamics().position.x > m_balls[1]->getDynamics().position.x;
        for (size_t i = 0; i < m_space->getNumContacts(); ++i) {
            const CollisionContact& c = m_space->getContactList()[i];
            if (m_firstContact < 0) m_firstContact = m_time;
            ++m_contacts;
            Vector g1 = static_cast<const iCollisionGeometry*>(c.g1)->getRigidBody()->getDynamics().position;
            Vector g2 = static_cast<const iCollisionGeometry*>(c.g2)->getRigidBody()->getDynamics().position;
            if (dot(c.normal, g2 - g1) <= 0.0f) m_badNormals++;
            if (!passed && std::fabs(c.depth - (1.0f - distance)) > 1e-3f) m_badDepths++;
        }
        if (++m_frames == kFrames) judge();
    }
    bool finished() const override { return m_frames >= kFrames; }
    void reset(int) override {}
    void restore(int) override {}
    void suspend() override {}
    void release() override {}
    void Delete() const override {
        // Any order is fine: a geometry whose body is gone is simply unbound.
        for (int i = 0; i < 2; ++i) {
            m_balls[i]->Delete();
            m_geoms[i]->Delete();
            m_objects[i]->Delete();
        }
        setDefaultCollisionSpace(nullptr);
        m_space->Delete();
        delete this;
    }

private:
    void judge() {
        std::printf("collision-only: first contact at %.3f s (expected 2.25 s), %d contacts, hits %d/%d\n",
                    m_firstContact, m_contacts, m_counters[0].hits, m_counters[1].hits);
        float frame = 0.016f;
        bool ok = true;
        ok &= check(m_firstContact >= 2.25f - frame && m_firstContact <= 2.25f + frame,
                    "first touch at 2.25 s");
        // Overlap lasts while |dx| < 1 m, i.e. 0.5 s of closing at 4 m/s: about 31 frames of 16 ms.
        ok &= check(m_contacts >= 29 && m_contacts <= 33, "contact reported every overlapping frame");
        ok &= check(m_counters[0].hits == m_contacts && m_counters[1].hits == m_contacts,
                    "HitWall on both sides");
        ok &= check(m_counters[0].normalsTowardOther && m_counters[1].normalsTowardOther,
                    "HitWall normals point toward the other body");
        ok &= check(m_badNormals == 0, "contact normals point at g2");
        ok &= check(m_badDepths == 0, "depth = r1 + r2 - distance");
        verdict = ok ? 0 : 1;
    }

    iCollisionSpace* m_space = nullptr;
    Ball* m_balls[2] = {};
    iCollisionGeometry* m_geoms[2] = {};
    iObject* m_objects[2] = {};
    HitCounter m_counters[2];
    int m_last = 0, m_frames = 0, m_contacts = 0, m_badNormals = 0, m_badDepths = 0;
    float m_time = 0, m_firstContact = -1;
};

} // namespace

int courseVerdict() { return verdict; }

CourseSetup createCourseDesign(iContext*) { return {new Design(), nullptr, 600}; }
