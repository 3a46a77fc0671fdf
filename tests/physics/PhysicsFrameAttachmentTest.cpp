// PhysicsFrameAttachmentTest.cpp - the seed's promise that attaching one PhysicsFrame to another also
// attaches their bodies: the pair moves and turns as one composite, and the frames drawn follow it.
#include "Frame.h"
#include "PhysicsTestSupport.h"
#include "iPhysicsFrame.h"
#include "iPhysicsSceneSettings.h"

#include <gtest/gtest.h>

#include <cmath>

using physics_test::ErrorRecorder;
using physics_test::kG;
using physics_test::SceneHolder;

namespace {

// A PhysicsFrame holding a small sphere (radius 0.1) of the given mass at p.
iPhysicsFrame* ball(float mass, const Vector& p) {
    iPhysicsFrame* f = CreatePhysicsFrame();
    RBDynamics* d = f->getDynamics();
    d->mass = mass;
    d->setInertiaTensor(getSphereInertiaTensor(mass, 0.1f));
    d->position = p;
    return f;
}

// Root A: 1 kg at the origin; child B: 3 kg at (2, 0, 0). Composite: 4 kg, centre C = (1.5, 0, 0), and
// about z I = 0.4 * 0.01 * (1 + 3) + 1 * 1.5^2 + 3 * 0.5^2 = 3.016 kg m^2.
constexpr float kPairIzz = 3.016f;

struct Pair {
    iPhysicsFrame* child; // made first, so the scene meets it before its parent
    iPhysicsFrame* root;
    explicit Pair(const Vector& at) : child(ball(3.0f, at + Vector(2, 0, 0))), root(ball(1.0f, at)) {}
    ~Pair() {
        child->Delete(); // children first: frames do not track children
        root->Delete();
    }
    RBDynamics& a() const { return *root->getDynamics(); }
    RBDynamics& b() const { return *child->getDynamics(); }
};

} // namespace

TEST(PhysicsFrameAttachment, AttachingFramesLinksTheirBodiesAndMassesAddUp) {
    SceneHolder h(60);
    Pair p{Vector()};
    p.child->attachTo(p.root);
    EXPECT_EQ(p.child->parent(), p.root);
    EXPECT_EQ(p.b().attachedTo(), &p.a());
    EXPECT_EQ(p.b().getMass(), 1.0f);          // the seed: the mass of the chain's root
    EXPECT_EQ(p.b().getCompositeMass(), 4.0f); // 1 + 3
    EXPECT_NEAR(p.b().getCompositeMassProperties().centre.x, 1.5f, 1e-6f);
    // A third frame on the child: 1 + 3 + 0.5 kg, the root's own mass unchanged.
    iPhysicsFrame* tip = ball(0.5f, Vector(3, 0, 0));
    tip->attachTo(p.child);
    EXPECT_EQ(tip->getDynamics()->attachmentRoot(), &p.a());
    EXPECT_EQ(tip->getDynamics()->getMass(), 1.0f);
    EXPECT_EQ(p.a().getCompositeMass(), 4.5f);
    // Attaching to a plain frame detaches the body from its body parent; nullptr detaches both.
    iFrame* plain = CreateFrame();
    tip->attachTo(plain);
    EXPECT_EQ(tip->parent(), plain);
    EXPECT_EQ(tip->getDynamics()->attachedTo(), nullptr);
    EXPECT_EQ(p.a().getCompositeMass(), 4.0f);
    p.child->attachTo(nullptr);
    EXPECT_EQ(p.child->parent(), nullptr);
    EXPECT_EQ(p.b().attachedTo(), nullptr);
    EXPECT_EQ(p.b().getMass(), 3.0f);
    EXPECT_NEAR((p.b().position - Vector(2, 0, 0)).length(), 0.0f, 1e-6f); // world pose kept throughout
    // A cycle through the bodies is refused, and nothing changes.
    p.child->attachTo(p.root);
    ErrorRecorder errors;
    p.root->attachTo(p.child);
    EXPECT_EQ(errors.count(), 1u);
    EXPECT_EQ(p.root->parent(), nullptr);
    EXPECT_EQ(p.a().attachedTo(), nullptr);
    tip->attachTo(nullptr);
    tip->Delete();
    plain->Delete();
}

// The root moves sideways at 1 m/s, the child was at rest: attached, they move as one. Every frame the two
// bodies and the two drawn frames stay 2 m apart; after 1 s the composite's centre is at x = 1.5 + 1 and has
// fallen as 60 semi-implicit Euler steps give, g t^2 / 2 + g t dt / 2.
TEST(PhysicsFrameAttachment, AttachedFramesFallRigidlyTogether) {
    SceneHolder h(60);
    Pair p(Vector(0, 10, 0));
    p.a().velocity = Vector(1, 0, 0);
    p.child->attachTo(p.root);
    float worst = 0.0f, worstDrawn = 0.0f;
    for (int i = 0; i < 100; ++i) {
        h.run(10);
        worst =
            std::fmax(worst, std::fabs((p.b().getWorldPosition() - p.a().getWorldPosition()).length() - 2));
        worstDrawn =
            std::fmax(worstDrawn, std::fabs((p.child->position() - p.root->position()).length() - 2));
    }
    EXPECT_LT(worst, 1e-4f);
    EXPECT_LT(worstDrawn, 1e-4f);
    const float t = 1.0f, dt = 1.0f / 60.0f;
    Vector c = p.a().getCompositeMassProperties().centre;
    EXPECT_NEAR(c.x, 2.5f, 1e-4f);
    EXPECT_NEAR(10.0f - c.y, 0.5f * kG * t * t + 0.5f * kG * t * dt, 1e-3f);
    EXPECT_NEAR(10.0f - c.y, 0.5f * kG * t * t, 0.5f * kG * t * dt + 1e-3f);
    EXPECT_NEAR(p.a().angularVelocity.length(), 0.0f, 1e-6f); // uniform gravity turns nothing
}

// A torque or an impulse on the child turns the whole composite with the combined inertia about C.
TEST(PhysicsFrameAttachment, TorqueAndImpulseOnTheChildTurnTheComposite) {
    SceneHolder h(60);
    settingsOf(h.scene)->setGravity(Vector());
    Pair turned{Vector()};
    turned.child->attachTo(turned.root);
    turned.b().temporalTorque = Vector(0, 0, 6.0f);
    // J = (0, 4, 0) at B's centre: C gets 4 / 4 = 1 m/s, and w = (B - C) x J / I_zz = 0.5 * 4 / 3.016 rad/s.
    Pair hit(Vector(0, 0, 10));
    hit.child->attachTo(hit.root);
    hit.b().ApplyImpulse(Vector(0, 4, 0), Vector(2, 0, 10));
    const float w = 0.5f * 4.0f / kPairIzz;
    EXPECT_NEAR(hit.a().angularVelocity.z, w, 1e-5f);
    h.run(17); // one step: the torque gives dw = tau dt / I_zz
    EXPECT_NEAR(turned.a().angularVelocity.z, 6.0f / 60.0f / kPairIzz, 1e-6f);
    h.run(1000); // 60 more steps: 61 in all, t = 61 / 60 s after the impulse
    const float t = 61.0f / 60.0f;
    // B circles C (z is a principal axis, so w stays), and C moves up at 1 m/s.
    Vector c(1.5f, t, 10);
    Vector b = hit.b().getWorldPosition(), a = hit.a().getWorldPosition();
    EXPECT_NEAR(b.x, c.x + 0.5f * std::cos(w * t), 1e-4f);
    EXPECT_NEAR(b.y, c.y + 0.5f * std::sin(w * t), 1e-4f);
    EXPECT_NEAR(a.x, c.x - 1.5f * std::cos(w * t), 1e-4f);
    EXPECT_NEAR(a.y, c.y - 1.5f * std::sin(w * t), 1e-4f);
    EXPECT_NEAR(hit.a().angularVelocity.z, w, 1e-5f);
}

// A clone of an attached frame sits where the original is, in the same composite: 1 + 3 + 3 = 7 kg.
TEST(PhysicsFrameAttachment, CloneOfAnAttachedFrameJoinsTheSameComposite) {
    SceneHolder h(60);
    Pair p{Vector(0, 10, 0)};
    p.child->attachTo(p.root);
    iPhysicsFrame* copy = p.child->clone();
    EXPECT_EQ(copy->parent(), nullptr); // a root frame: a course framework's Frame does not expose its parent
    EXPECT_EQ(copy->getDynamics()->attachedTo(), &p.a());
    EXPECT_NEAR((copy->getDynamics()->getWorldPosition() - Vector(2, 10, 0)).length(), 0.0f, 1e-5f);
    EXPECT_EQ(p.a().getCompositeMass(), 7.0f);
    h.run(100);
    EXPECT_NEAR((copy->position() - p.child->position()).length(), 0.0f, 1e-5f); // drawn together
    copy->Delete();
}
