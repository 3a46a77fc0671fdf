// AttachmentTest.cpp - attachment chains as one composite body: total mass, rotation about the combined
// centre of mass with the combined (parallel-axis) inertia, impulses on any part, rigid riding, detaching.
#include "Frame.h"
#include "PhysicsTestSupport.h"
#include "iPhysicsSceneSettings.h"

#include <gtest/gtest.h>

#include <cmath>

using physics_test::SceneHolder;

namespace {

// A: 1 kg at the origin, B: 3 kg at (2, 0, 0), small spheres (radius 0.1). Composite: 4 kg, centre
// C = (1.5, 0, 0); about z: I = 0.4 * 0.01 * (1 + 3) + 1 * 1.5^2 + 3 * 0.5^2 = 0.016 + 2.25 + 0.75 = 3.016.
struct Dumbbell {
    iRigidBody* a;
    iRigidBody* b;
    Dumbbell() : a(CreateRigidBody(nullptr)), b(CreateRigidBody(nullptr)) {
        a->getDynamics().setInertiaTensor(getSphereInertiaTensor(1.0f, 0.1f));
        b->getDynamics().mass = 3.0f;
        b->getDynamics().setInertiaTensor(getSphereInertiaTensor(3.0f, 0.1f));
        b->getDynamics().position = Vector(2, 0, 0);
        b->getDynamics().attachTo(&a->getDynamics());
    }
};
constexpr float IZZ = 3.016f;
const Vector C(1.5f, 0, 0);

} // namespace

TEST(Attachment, CompositeMassAndLinks) {
    SceneHolder h(60);
    Dumbbell d;
    RBDynamics& a = d.a->getDynamics();
    RBDynamics& b = d.b->getDynamics();
    EXPECT_EQ(b.attachedTo(), &a);
    EXPECT_EQ(b.attachmentRoot(), &a);
    // The seed: getMass() is the mass of the body at the root of the chain (A, 1 kg), from any part;
    // getCompositeMass() is the whole composite's, 1 + 3 = 4 kg.
    EXPECT_EQ(a.getMass(), 1.0f);
    EXPECT_EQ(b.getMass(), 1.0f);
    EXPECT_EQ(a.getCompositeMass(), 4.0f);
    EXPECT_EQ(b.getCompositeMass(), 4.0f);
    EXPECT_EQ(b.position, Vector(2, 0, 0)); // relative to A, which sits at the origin unrotated
    RBDynamics::MassProperties mp = b.getCompositeMassProperties();
    EXPECT_NEAR(mp.centre.x, 1.5f, 1e-6f);
    EXPECT_NEAR(mp.inertia.m33, IZZ, 1e-5f);
    EXPECT_NEAR(mp.inertia.m11, 0.016f, 1e-6f);
    // Attaching a body to its own descendant is refused.
    physics_test::ErrorRecorder errors;
    a.attachTo(&b);
    EXPECT_EQ(errors.count(), 1u);
    EXPECT_EQ(a.attachedTo(), nullptr);
}

// Spinning at w = 1 rad/s about z with the centre C at rest: both bodies circle C, the whole turning
// rigidly: B = C + 0.5 (cos t, sin t, 0), A = C - 1.5 (cos t, sin t, 0). z is a principal axis of the
// composite, so w stays constant and the exact-exponential rotation update is exact to round-off.
TEST(Attachment, CompositeRotatesAboutTheCombinedCentreOfMass) {
    SceneHolder h(60);
    settingsOf(h.scene)->setGravity(Vector());
    Dumbbell d;
    RBDynamics& a = d.a->getDynamics();
    RBDynamics& b = d.b->getDynamics();
    a.angularVelocity = Vector(0, 0, 1);
    a.velocity = cross(Vector(0, 0, 1), a.position - C); // root's COM velocity with C at rest
    iFrame* frameB = CreateFrame();
    d.b->attach(frameB);
    h.run(1000);
    const float t = 1.0f;
    Vector wb = b.getWorldPosition(), wa = a.getWorldPosition();
    EXPECT_NEAR(wb.x, 1.5f + 0.5f * std::cos(t), 1e-5f);
    EXPECT_NEAR(wb.y, 0.5f * std::sin(t), 1e-5f);
    EXPECT_NEAR(wa.x, 1.5f - 1.5f * std::cos(t), 1e-5f);
    EXPECT_NEAR(wa.y, -1.5f * std::sin(t), 1e-5f);
    EXPECT_NEAR(a.angularMomentum.z, IZZ, 1e-4f); // L about C = I_composite w
    // The drawn frame of the attached body follows it (one step behind).
    EXPECT_NEAR(frameB->position().x, 1.5f + 0.5f * std::cos(t - 1.0f / 60), 1e-5f);
    // Velocity of a point on the composite: w x (p - C).
    Vector vb = b.getVelocityAtWorldPoint(wb);
    EXPECT_NEAR(vb.x, -0.5f * std::sin(t), 1e-5f);
    EXPECT_NEAR(vb.y, 0.5f * std::cos(t), 1e-5f);
    d.b->attach(nullptr);
    frameB->Delete();
}

// A torque on the root turns the composite with the combined inertia: dw = tau dt / I_zz; the centre of
// mass stays where it is.
TEST(Attachment, TorqueUsesTheCombinedInertia) {
    SceneHolder h(60);
    settingsOf(h.scene)->setGravity(Vector());
    Dumbbell d;
    RBDynamics& a = d.a->getDynamics();
    a.temporalTorque = Vector(0, 0, 6.0f);
    h.scene->update(17);
    EXPECT_NEAR(a.angularVelocity.z, 6.0f / 60.0f / IZZ, 1e-6f);
    RBDynamics::MassProperties mp = a.getCompositeMassProperties();
    EXPECT_NEAR(mp.centre.x, 1.5f, 1e-6f);
    EXPECT_NEAR(mp.centre.y, 0.0f, 1e-6f);
}

// An impulse on any part acts on the composite: through C it only translates (dv = J / M), at B's centre it
// also turns it: dw = (r x J) / I with r = B - C.
TEST(Attachment, ImpulsesOnAPartMoveTheComposite) {
    Dumbbell d; // no scene needed: impulses are RBDynamics functions
    RBDynamics& a = d.a->getDynamics();
    RBDynamics& b = d.b->getDynamics();
    b.ApplyImpulse(Vector(0, 4, 0), C);
    EXPECT_NEAR(a.velocity.y, 1.0f, 1e-6f);
    EXPECT_NEAR(a.angularVelocity.length(), 0.0f, 1e-6f);
    b.ApplyImpulse(Vector(0, 4, 0), Vector(2, 0, 0));
    EXPECT_NEAR(a.angularVelocity.z, 0.5f * 4.0f / IZZ, 1e-5f);
    // The root's velocity is its own COM's: V_C + w x (A - C).
    EXPECT_NEAR(a.velocity.y, 2.0f + a.angularVelocity.z * -1.5f, 1e-5f);
    EXPECT_NEAR(b.getVelocityAtWorldPoint(C).y, 2.0f, 1e-5f);
    d.a->Delete();
    d.b->Delete();
}

// Gravity pulls the composite as one (no spurious rotation); detaching keeps B's world pose and velocity.
TEST(Attachment, CompositeFallsAsOneAndDetachesSeamlessly) {
    SceneHolder h(60);
    Dumbbell d;
    RBDynamics& a = d.a->getDynamics();
    RBDynamics& b = d.b->getDynamics();
    h.run(500);
    EXPECT_NEAR(a.angularVelocity.length(), 0.0f, 1e-6f);
    Vector wb = b.getWorldPosition();
    EXPECT_NEAR(wb.x, 2.0f, 1e-5f);
    EXPECT_NEAR(wb.y, a.position.y, 1e-5f);
    Vector vBefore = b.getVelocityAtWorldPoint(wb);
    b.attachTo(nullptr);
    EXPECT_EQ(b.attachedTo(), nullptr);
    EXPECT_NEAR((b.position - wb).length(), 0.0f, 1e-6f);
    EXPECT_NEAR((b.velocity - vBefore).length(), 0.0f, 1e-6f);
    EXPECT_EQ(a.getCompositeMass(), 1.0f);
    // B is a root again: getMass() is its own mass.
    EXPECT_EQ(b.getMass(), 3.0f);
    h.run(100); // both fall on, separately
    EXPECT_NEAR(b.velocity.y, a.velocity.y, 1e-5f);
}

// attachmentEpoch: a cache of roots holds exactly while it stands. Every change of a link moves it (attach,
// detach, a parent's or a child's destruction); what changes no link (a refused attachment, detaching a root,
// moving a body) leaves it.
TEST(Attachment, EveryLinkChangeAndOnlyOneMovesTheAttachmentEpoch) {
    RBDynamics a, b, c;
    auto epoch = [] { return RBDynamics::attachmentEpoch(); };
    unsigned long long before = epoch();
    b.attachTo(&a);
    EXPECT_NE(epoch(), before);
    EXPECT_EQ(b.attachmentRoot(), &a);
    before = epoch();
    a.attachTo(&b); // a descendant: refused, no link changes
    b.attachTo(&b);
    c.attachTo(nullptr); // already a root
    c.position = Vector(1, 2, 3);
    EXPECT_EQ(epoch(), before);
    EXPECT_EQ(a.attachmentRoot(), &a);
    c.attachTo(&b);
    EXPECT_NE(epoch(), before);
    EXPECT_EQ(c.attachmentRoot(), &a);
    before = epoch();
    c.attachTo(nullptr);
    EXPECT_NE(epoch(), before);
    EXPECT_EQ(c.attachmentRoot(), &c);
    {
        RBDynamics child;
        child.attachTo(&c);
        before = epoch();
    } // the child goes: its link with it
    EXPECT_NE(epoch(), before);
    {
        RBDynamics parent;
        c.attachTo(&parent);
        before = epoch();
    } // the parent goes: c is a root again
    EXPECT_NE(epoch(), before);
    EXPECT_EQ(c.attachmentRoot(), &c);
}
