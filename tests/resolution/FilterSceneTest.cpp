// FilterSceneTest.cpp - collision filters, sensors and contact events through the whole simulation
// (scene->update(now) at 60 Hz): a bullet fired from inside its shooter, a pickup sensor on a projectile's
// path, a ball resting on a table and rolling off, and an observer destroyed without detaching.
#include "iCOBB.h"
#include "iCPlane.h"
#include "iCSphere.h"
#include "iCollisionFilter.h"
#include "iCollisionListener.h"
#include "iContactEvents.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"
#include "iSimpleCollisionSpace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

constexpr std::uint32_t kPlayer = 1u << 1, kWall = 1u << 2, kBullet = 1u << 3, kPickup = 1u << 4;

// A scene with its own space, updated frame by frame at 60 Hz (one step an update).
struct Stage {
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    iCollisionSpace* space = CreateSimpleCollisionSpace();
    std::vector<iCollisionGeometry*> geoms;
    std::vector<iRigidBody*> bodies;
    int frame = 0;
    explicit Stage(Vector gravity) {
        settingsOf(scene)->setGravity(gravity);
        scene->setNewGlobalCollisionSpace(space);
        scene->update(0);
    }
    ~Stage() {
        for (iCollisionGeometry* g : geoms) g->Delete();
        for (iRigidBody* b : bodies) b->Delete();
        scene->Delete();
        space->Delete();
    }
    iRigidBody* body(const Vector& at, float mass, bool fixed = false) {
        iRigidBody* b = CreateRigidBody(nullptr);
        b->getDynamics().position = at;
        b->getDynamics().mass = mass;
        if (fixed) b->getDynamics().physicsType = PHYS_FixedInSpace;
        bodies.push_back(b);
        return b;
    }
    iCollisionGeometry* keep(iCollisionGeometry* g, std::uint32_t layer, std::uint32_t mask = ~0u,
                             bool sensor = false) {
        filterOf(g)->setLayer(layer);
        filterOf(g)->setMask(mask);
        filterOf(g)->setSensor(sensor);
        geoms.push_back(g);
        return g;
    }
    void next() {
        ++frame;
        scene->update(int(std::ceil(frame * 1000.0 / 60.0)));
    }
};

// The kinds of the calls about one pair per update ('b', 'p', 'e'; '.' for an update without one).
struct PairLog final : ContactObserver {
    const iRigidBody* watched;
    std::string kinds;
    std::vector<ContactPair> pairs; // parallel to kinds
    explicit PairLog(const iRigidBody* b) : watched(b) {}
    void take(char k, const ContactPair& p) {
        if (p.bodyA != watched && p.bodyB != watched) return;
        kinds += k;
        pairs.push_back(p);
    }
    void onBegin(const ContactPair& p) override { take('b', p); }
    void onPersist(const ContactPair& p) override { take('p', p); }
    void onEnd(const ContactPair& p) override { take('e', p); }
};

struct CountHits final : iCollisionListener {
    int hits = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++hits; }
};

// A bullet fired at 100 m/s along x from startX (the shooter, a 1 m wide box, is centred at 0; the wall's
// face is at x = 9.5), followed for 0.5 s: its x-velocity at every frame until it reaches the wall, its
// largest x and last x-velocity, and where the shooter went.
struct Shot {
    std::vector<float> vxBeforeWall;
    float maxX = -1e9f, lastVx = 0;
    Vector shooterMoved;
};
Shot fire(bool maskOutShooter, float startX) {
    Stage s(Vector(0, 0, 0));
    iRigidBody* shooter = s.body(Vector(0, 0, 0), 80.0f);
    s.keep(CreateCOBB(shooter, Vector(0.5f, 1.0f, 0.5f)), kPlayer);
    iRigidBody* wall = s.body(Vector(10, 0, 0), 1.0f, true);
    s.keep(CreateCOBB(wall, Vector(0.5f, 3, 3)), kWall);
    iRigidBody* bullet = s.body(Vector(startX, 0, 0), 0.01f);
    bullet->getDynamics().restitution = 0.0f;
    wall->getDynamics().restitution = 0.0f;
    s.keep(CreateCSphere(bullet, 0.05f), kBullet, maskOutShooter ? ~kPlayer : ~0u);
    bullet->getDynamics().velocity = Vector(100, 0, 0);
    Shot shot;
    for (int i = 0; i < 30; ++i) {
        s.next();
        if (bullet->getDynamics().position.x < 9.0f)
            shot.vxBeforeWall.push_back(bullet->getDynamics().velocity.x);
        shot.maxX = std::fmax(shot.maxX, bullet->getDynamics().position.x);
    }
    shot.lastVx = bullet->getDynamics().velocity.x;
    shot.shooterMoved = shooter->getDynamics().position;
    return shot;
}

} // namespace

// The bullet's mask leaves out the shooter's layer: fired from inside the shooter, or from behind it
// through it, it flies at exactly 100 m/s until the wall (no gravity, no drag), the shooter does not move,
// and it stops at the wall (restitution 0; its centre never past the face minus its radius, 9.45 m, plus
// 1 cm of slop). The control: without the mask the shot from behind is stopped by the shooter and shoves it.
TEST(FilterScene, BulletPassesOutOfItsShooterAndStopsAtAWall) {
    for (float startX : {0.0f, -3.0f}) {
        const Shot masked = fire(true, startX);
        ASSERT_GE(masked.vxBeforeWall.size(), 5u);
        for (float vx : masked.vxBeforeWall) EXPECT_EQ(vx, 100.0f) << startX;
        EXPECT_EQ(masked.shooterMoved.length(), 0.0f);
        EXPECT_LT(masked.maxX, 9.45f + 0.01f); // never through the 1 m wall
        EXPECT_GT(masked.maxX, 9.45f - 0.01f); // and it reached it
        EXPECT_LT(std::fabs(masked.lastVx), 1.0f);
    }
    const Shot unmasked = fire(false, -3.0f);
    EXPECT_LT(unmasked.maxX, 0.0f); // stopped at the shooter's back face (x = -0.5)
    EXPECT_GT(unmasked.shooterMoved.x, 0.0f);
}

// A pickup sensor (radius 1, fixed, at (1.5, 1.2, 0)) on the path of a ball of radius 0.5 thrown as a
// projectile: the ball's path is exactly that of the same throw in a scene without the pickup (bit for bit),
// the pickup gives no HitWall, and contact events say begin once when the centres come within 1.5 m,
// persist while within, end once when apart: computed from the ball's positions, frame by frame.
TEST(FilterScene, PickupSensorReportsOverlapWithoutShovingThePlayer) {
    const Vector pickupAt(1.5f, 1.2f, 0);
    auto throwBall = [&](bool withPickup, std::vector<Vector>& path, std::string& kinds, int& hits) {
        Stage s(Vector(0, -9.81f, 0));
        iRigidBody* player = s.body(Vector(0, 1, 0), 1.0f);
        s.keep(CreateCSphere(player, 0.5f), kPlayer, ~0u);
        if (withPickup) {
            iRigidBody* pickup = s.body(pickupAt, 1.0f, true);
            s.keep(CreateCSphere(pickup, 1.0f), kPickup, kPlayer, true);
        }
        PairLog log(player);
        CountHits listener;
        player->attachListener(&listener);
        contactEventsOf(s.space)->addObserver(&log);
        player->getDynamics().velocity = Vector(3, 4, 0);
        for (int i = 0; i < 60; ++i) {
            const size_t before = log.kinds.size();
            s.next();
            if (log.kinds.size() == before) {
                log.kinds += '.';
                log.pairs.emplace_back();
            }
            path.push_back(player->getDynamics().position);
        }
        kinds = log.kinds;
        hits = listener.hits;
        player->detachListener(&listener);
    };
    std::vector<Vector> path, free;
    std::string kinds, none;
    int hits = 0, freeHits = 0;
    throwBall(true, path, kinds, hits);
    throwBall(false, free, none, freeHits);
    ASSERT_EQ(path.size(), free.size());
    for (size_t i = 0; i < path.size(); ++i) {
        EXPECT_EQ(path[i].x, free[i].x) << i;
        EXPECT_EQ(path[i].y, free[i].y) << i;
        EXPECT_EQ(path[i].z, free[i].z) << i;
    }
    // The throw itself: x = 3 t (no horizontal force).
    EXPECT_NEAR(path.back().x, 3.0f, 1e-3f);
    EXPECT_EQ(hits, 0);
    // What the events must say, from the distances at the pose each step detected contacts at: its start
    // (the previous frame's end pose; the throw's start for the first).
    std::string expected;
    bool was = false;
    for (size_t i = 0; i < path.size(); ++i) {
        const Vector p = i == 0 ? Vector(0, 1, 0) : path[i - 1];
        const float d = (p - pickupAt).length();
        ASSERT_GT(std::fabs(d - 1.5f), 1e-3f) << "a frame on the boundary: move the pickup";
        const bool in = d < 1.5f;
        expected += in ? (was ? 'p' : 'b') : (was ? 'e' : '.');
        was = in;
    }
    EXPECT_EQ(kinds, expected);
    EXPECT_EQ(std::count(kinds.begin(), kinds.end(), 'b'), 1);
    EXPECT_EQ(std::count(kinds.begin(), kinds.end(), 'e'), 1);
    EXPECT_EQ(none, std::string(60, '.'));
}

// A ball resting on a table (falling asleep), pushed, rolling off its edge onto the floor: the ball-table
// pair begins once, persists through sleep and the roll, and ends once, when the ball's centre is past the
// edge (x = 2) and below its resting height; the floor pair then begins once, when the ball reaches it.
TEST(FilterScene, BallRestingThenRollingOffATable) {
    Stage s(Vector(0, -9.81f, 0));
    iRigidBody* table = s.body(Vector(0, 0.5f, 0), 1.0f, true);
    s.keep(CreateCOBB(table, Vector(2, 0.5f, 2)), 1);
    s.keep(CreateCPlane(nullptr, Vector(0, 1, 0), 0.0f), 1);
    iRigidBody* ball = s.body(Vector(1, 1.249f, 0), 1.0f);
    s.keep(CreateCSphere(ball, 0.25f), 1);
    for (iRigidBody* b : {table, ball}) b->getDynamics().restitution = 0.0f; // no bounces on the floor
    PairLog log(ball);
    contactEventsOf(s.space)->addObserver(&log);
    std::string tableKinds, floorKinds;
    float endX = 0, endY = 0, floorY = 0;
    bool slept = false;
    for (int i = 0; i < 240; ++i) {
        if (i == 90) ball->getDynamics().velocity = Vector(4, 0, 0); // the push (wakes it)
        const size_t before = log.kinds.size();
        s.next();
        slept = slept || ball->getDynamics().sleeping;
        for (size_t c = before; c < log.kinds.size(); ++c) { // this update's calls, by pair
            const char k = log.kinds[c];
            const bool onTable = log.pairs[c].bodyA == table || log.pairs[c].bodyB == table;
            (onTable ? tableKinds : floorKinds) += k;
            if (onTable && k == 'e') {
                endX = ball->getDynamics().position.x;
                endY = ball->getDynamics().position.y;
            }
            if (!onTable && k == 'b') floorY = ball->getDynamics().position.y;
        }
    }
    EXPECT_TRUE(slept) << "the resting phase must include sleep";
    ASSERT_FALSE(tableKinds.empty());
    EXPECT_EQ(tableKinds.front(), 'b');
    EXPECT_EQ(tableKinds.back(), 'e');
    EXPECT_EQ(std::count(tableKinds.begin(), tableKinds.end(), 'b'), 1);
    EXPECT_EQ(std::count(tableKinds.begin(), tableKinds.end(), 'e'), 1);
    EXPECT_GT(endX, 2.0f);
    EXPECT_LT(endY, 1.25f);
    ASSERT_FALSE(floorKinds.empty());
    EXPECT_EQ(floorKinds.front(), 'b');
    EXPECT_NEAR(floorY, 0.25f, 0.05f); // its bottom on the floor
}

// An observer destroyed without removeObserver while a pair touches is never called by later updates
// (under ASan, a call would be a heap-use-after-free); the other observer goes on hearing onPersist.
TEST(FilterScene, ObserverDestroyedWithoutDetachingIsNeverCalled) {
    Stage s(Vector(0, -9.81f, 0));
    s.keep(CreateCPlane(nullptr, Vector(0, 1, 0), 0.0f), 1);
    iRigidBody* ball = s.body(Vector(0, 0.249f, 0), 1.0f);
    s.keep(CreateCSphere(ball, 0.25f), 1);
    PairLog kept(ball);
    auto* doomed = new PairLog(ball);
    contactEventsOf(s.space)->addObserver(&kept);
    contactEventsOf(s.space)->addObserver(doomed);
    s.next();
    EXPECT_EQ(doomed->kinds, "b");
    delete doomed;
    for (int i = 0; i < 10; ++i) s.next();
    EXPECT_EQ(kept.kinds, "b" + std::string(10, 'p'));
}
