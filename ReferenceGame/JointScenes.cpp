// JointScenes.cpp - the demo scenes built with joints (JointScenes.h): what each is and why it is built so.
#include "JointScenes.h"

#include "MathDefinitions.h"
#include "RBDynamics.h"
#include "World.h"
#include "iBallJoint.h"
#include "iDistanceJoint.h"
#include "iHingeJoint.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iRigidBody.h"
#include "iRope.h"
#include "iSoftBody.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace {

// A string from the world point pivot to the centre of body: slack up to its length now, never longer.
void hangOnString(World& world, iPhysicsFrame* body, const Vector& pivot) {
    const Vector centre = body->getDynamics()->position;
    iDistanceJoint* string = world.joint(CreateDistanceJoint(body->getRB(), nullptr, centre, pivot));
    if (string) string->setLimits(0.0f, length(pivot - centre));
}

} // namespace

void buildStringCradle(World& world, int released) {
    world.ground();
    // A cradle is a row of separate two-ball impacts, each ball stopping as it starts the next. The engine
    // resolves the contacts found at a step's start, so each impact must get a step of its own: at 120 Hz a
    // ball at the impact speed (2.4 m/s) moves 2.0 cm a step, less than the quarter diameter (2.5 cm) beyond
    // which the continuous sweep puts a ball back at its first touch. At 60 Hz that put-back leaves the
    // released ball behind it 3 cm inside it, and the three are solved as one simultaneous impact, which
    // spreads the momentum instead of passing it on (a limitation of the sweep, reported).
    settingsOf(world.scene())->setStepRate(120);
    const int balls = 5;
    const float radius = 0.05f, gap = 0.001f, stringDrop = 1.0f, barY = 2.0f, spread = 0.3f;
    const float spacing = 2 * radius + gap;
    // Swung out on its string by theta, a ball rises L (1 - cos theta): that is the raise.
    const float theta = std::acos(1.0f - kCradleRaise / stringDrop);
    for (int i = 0; i < balls; ++i) {
        const Vector top(spacing * (i - 2), barY, 0); // the middle of its two pivots
        // The released balls all turn by theta about their own pivots, so they keep their 1 mm gaps.
        const float a = i < released ? theta : 0.0f;
        const Vector at = top + Vector(-std::sin(a), -std::cos(a), 0) * stringDrop;
        iPhysicsFrame* ball = world.sphere(at, radius, 1.0f);
        RBDynamics* d = ball->getDynamics();
        d->restitution = 1.0f;
        d->friction = 0.0f;
        // Two strings in a V, their pivots in front of and behind the ball: it can only swing about the
        // line through them, in the plane of the row.
        hangOnString(world, ball, top + Vector(0, 0, spread));
        hangOnString(world, ball, top + Vector(0, 0, -spread));
    }
    world.name(world.bodies().front(), "cue");
    world.name(world.bodies().back(), "last");
}

void buildHingeChain(World& world, int links) {
    world.ground();
    // 0.2 m from hinge to hinge; each box 1 cm shorter, so that neighbours never touch (their contacts would
    // be found and then skipped, as the bodies are joined: work for nothing).
    const float pitch = 0.2f;
    const Vector half(0.02f, 0.5f * pitch - 0.005f, 0.02f), top(0, 5, 0);
    iRigidBody* above = nullptr;
    for (int i = 0; i < links; ++i) {
        const Vector anchor = top - Vector(0, pitch * i, 0);
        iPhysicsFrame* link = world.box(anchor - Vector(0, 0.5f * pitch, 0), half, 0.5f);
        // Each link hangs from the one above at its top end; the first from the world.
        world.joint(CreateHingeJoint(link->getRB(), above, anchor, Vector(0, 0, 1)));
        above = link->getRB();
    }
    world.name(world.bodies().front(), "top");
    RBDynamics* bottom = world.name(world.bodies().back(), "bottom")->getDynamics();
    // Kicked sideways at its centre: the chain swings in its plane.
    bottom->ApplyImpulse(Vector(0.75f, 0, 0), bottom->position);
}

namespace {
const Vector kDoorHinge(0, 1.02f, 0);       // on the door's edge, 2 cm above the floor's level
const Vector kDoorHalf(0.45f, 1.0f, 0.03f); // 0.9 m wide, 2 m tall
} // namespace

void buildDoor(World& world) {
    world.ground();
    iPhysicsFrame* door =
        world.name(world.box(kDoorHinge + Vector(kDoorHalf.x, 0, 0), kDoorHalf, 8.0f), "door");
    // The axis points down: B (the world) turning about it relative to A (the door) is the door turning
    // about +y, so the angle grows as the door opens toward -z.
    iHingeJoint* hinge = world.joint(CreateHingeJoint(door->getRB(), nullptr, kDoorHinge, Vector(0, -1, 0)));
    if (!hinge) return;
    hinge->setLimits(kDoorClosed, kDoorOpen);
    hinge->setLimitsEnabled(true);
    hinge->setMotor(kDoorMotorSpeed, kDoorMotorTorque);
}

void throwAtDoor(World& world, int frame) {
    iPhysicsFrame* door = world.named("door");
    if (frame != kDoorThrowFrame || !door) return;
    // At the door's centre, along the way the centre moves when the door opens (+y x the radius): the hit
    // pushes the door against its stop.
    const Vector centre = door->getDynamics()->position, radius = centre - kDoorHinge;
    const Vector push = normal(cross(Vector(0, 1, 0), radius));
    const float distance = 2.5f, speed = 6.0f, flight = distance / speed;
    const Vector g = settingsOf(world.scene())->getGravity();
    RBDynamics* ball = world.name(world.sphere(centre - push * distance, 0.15f, 2.0f), "ball")->getDynamics();
    // Aimed up by half the fall of its flight, so that it arrives at the centre's height.
    ball->velocity = push * speed - g * (0.5f * flight);
}

namespace {

// The ragdoll is laid out standing (feet at y = 0, facing +z), then turned by a rotation about the hips
// and lifted: each part's centre and each joint's anchor and axis go through place().
struct Pose {
    Matrix turn;
    Vector hips, lift;
    Vector place(const Vector& p) const { return (p - hips) * turn + lift; }
    Vector axis(const Vector& v) const { return v * turn; }
};

struct Part {
    const char* name;
    Vector centre, half;
    float mass;
};

// Standing: legs 0.02..0.84 m, torso 0.86..1.40, head 1.42..1.64, arms hanging 1 cm clear of the torso.
const Part kParts[] = {
    {"torso", Vector(0, 1.13f, 0), Vector(0.17f, 0.27f, 0.1f), 25.0f},
    {"head", Vector(0, 1.53f, 0), Vector(0.09f, 0.11f, 0.09f), 5.0f},
    {"upper-arm-left", Vector(-0.23f, 1.22f, 0), Vector(0.05f, 0.15f, 0.05f), 2.5f},
    {"lower-arm-left", Vector(-0.23f, 0.91f, 0), Vector(0.045f, 0.14f, 0.045f), 1.5f},
    {"upper-arm-right", Vector(0.23f, 1.22f, 0), Vector(0.05f, 0.15f, 0.05f), 2.5f},
    {"lower-arm-right", Vector(0.23f, 0.91f, 0), Vector(0.045f, 0.14f, 0.045f), 1.5f},
    {"upper-leg-left", Vector(-0.1f, 0.64f, 0), Vector(0.07f, 0.2f, 0.07f), 7.0f},
    {"lower-leg-left", Vector(-0.1f, 0.22f, 0), Vector(0.06f, 0.2f, 0.06f), 4.0f},
    {"upper-leg-right", Vector(0.1f, 0.64f, 0), Vector(0.07f, 0.2f, 0.07f), 7.0f},
    {"lower-leg-right", Vector(0.1f, 0.22f, 0), Vector(0.06f, 0.2f, 0.06f), 4.0f},
};
enum PartIndex {
    Torso,
    Head,
    UpperArmL,
    LowerArmL,
    UpperArmR,
    LowerArmR,
    UpperLegL,
    LowerLegL,
    UpperLegR,
    LowerLegR
};

} // namespace

void buildRagdoll(World& world) {
    world.ground();
    Pose pose{rotate(normal(Vector(1, 0.2f, 0.3f)), 1.2f), Vector(0, 0.85f, 0), Vector(0, 0, 0)};
    // Lifted so that its lowest corner starts 0.5 m above the floor.
    float lowest = 1e9f;
    for (const Part& p : kParts)
        for (int c = 0; c < 8; ++c) {
            const Vector corner(c & 1 ? p.half.x : -p.half.x, c & 2 ? p.half.y : -p.half.y,
                                c & 4 ? p.half.z : -p.half.z);
            lowest = std::min(lowest, pose.place(p.centre + corner).y);
        }
    pose.lift = Vector(0, 0.5f - lowest, 0);
    iRigidBody* body[10];
    for (int i = 0; i < 10; ++i) {
        const Part& p = kParts[i];
        body[i] = world.box(pose.place(p.centre), p.half, p.mass, pose.turn)->getRB();
    }
    world.name(world.bodies().front(), "torso");
    world.name(world.bodies()[1], "head");
    // The limb (A) on its parent (B) at the standing pose's anchor; twist axes point from joint to limb.
    auto ball = [&](int limb, int parent, const Vector& at, const Vector& twist, float cone,
                    float twistLimit) {
        iBallJoint* j =
            world.joint(CreateBallJoint(body[limb], body[parent], pose.place(at), pose.axis(twist)));
        if (!j) return;
        j->setConeLimit(cone);
        j->setTwistLimits(-twistLimit, twistLimit);
    };
    ball(Head, Torso, Vector(0, 1.41f, 0), Vector(0, 1, 0), 0.6f, 0.7f);
    ball(UpperArmL, Torso, Vector(-0.23f, 1.38f, 0), Vector(0, -1, 0), 1.4f, 0.8f);
    ball(UpperArmR, Torso, Vector(0.23f, 1.38f, 0), Vector(0, -1, 0), 1.4f, 0.8f);
    ball(UpperLegL, Torso, Vector(-0.1f, 0.85f, 0), Vector(0, -1, 0), 1.0f, 0.4f);
    ball(UpperLegR, Torso, Vector(0.1f, 0.85f, 0), Vector(0, -1, 0), 1.0f, 0.4f);
    // Hinges bend one way from straight (angle 0): B (the upper part) turning about the axis relative to A
    // (the lower part). Elbows about +x bend the forearm forward (+z), knees about -x the shin back.
    auto hinge = [&](int limb, int parent, const Vector& at, const Vector& axis) {
        iHingeJoint* j =
            world.joint(CreateHingeJoint(body[limb], body[parent], pose.place(at), pose.axis(axis)));
        if (!j) return;
        j->setLimits(0.0f, 2.4f);
        j->setLimitsEnabled(true);
    };
    hinge(LowerArmL, UpperArmL, Vector(-0.23f, 1.06f, 0), Vector(1, 0, 0));
    hinge(LowerArmR, UpperArmR, Vector(0.23f, 1.06f, 0), Vector(1, 0, 0));
    hinge(LowerLegL, UpperLegL, Vector(-0.1f, 0.43f, 0), Vector(-1, 0, 0));
    hinge(LowerLegR, UpperLegR, Vector(0.1f, 0.43f, 0), Vector(-1, 0, 0));
}

void buildRopeBridge(World& world) {
    world.ground();
    const int segments = 30, links = segments - 1;
    const float span = 6.0f, height = 2.0f, length = 1.05f * span;
    iRope* rope =
        CreateRope(Vector(-0.5f * length, height, 0), Vector(0.5f * length, height, 0), segments, 0.2f);
    if (!rope) return;
    // Laid out hanging, not straight (a rope cannot sag between its pins without stretching), on the circular
    // arc through the pins whose equal chords are the links: at rest but for the arc not being a catenary.
    // The arc's half angle a: each link subtends 2a / links, radius link / (2 sin(a / links)), and the pins
    // are 2 r sin a = span apart; by bisection (the span shrinks as a grows).
    const float link = length / float(links);
    auto radius = [&](float a) { return link / (2 * std::sin(a / float(links))); };
    float lo = 1e-4f, hi = 1.5f;
    for (int i = 0; i < 60; ++i) {
        const float mid = 0.5f * (lo + hi);
        (2 * radius(mid) * std::sin(mid) > span ? lo : hi) = mid;
    }
    const float a = lo, r = radius(a);
    const Vector centre(0, height + r * std::cos(a), 0);
    for (int i = 0; i < segments; ++i) { // a written position is a teleport: never swept
        const float angle = -a + 2 * a * float(i) / float(links);
        rope->getSegments()[i]->getDynamics().position =
            centre + Vector(std::sin(angle), -std::cos(angle), 0) * r;
    }
    // A sphere of 0.1 m on each segment (0.217 m apart): the box cannot slip between them; neighbours,
    // joined, do not collide.
    world.rope(rope, 0.1f);
    rope->pin(true, nullptr);
    rope->pin(false, nullptr);
}

void dropOnBridge(World& world, int frame) {
    // Onto the middle of the hanging rope (0.84 m below its pins), from 0.6 m above it.
    if (frame == kBridgeDropFrame)
        world.name(world.box(Vector(0, 1.9f, 0), Vector(0.25f, 0.15f, 0.25f), 2.0f), "box");
}

void buildWreckingBall(World& world) {
    world.ground();
    // Laid out straight from the pivot, pulled out toward -x; each link 1 cm shorter than the pitch, so that
    // neighbours never touch. A link's y axis runs along the chain (its rotation about z: -kWreckAngle).
    const Vector down(-std::sin(kWreckAngle), -std::cos(kWreckAngle), 0);
    const Vector half(0.04f, 0.5f * kWreckPitch - 0.005f, 0.04f);
    const Matrix along = rotate(Vector(0, 0, 1), -kWreckAngle);
    iRigidBody* above = nullptr;
    for (int i = 0; i < kWreckLinks; ++i) {
        iPhysicsFrame* link =
            world.box(kWreckPivot + down * (kWreckPitch * (float(i) + 0.5f)), half, 0.5f, along);
        world.joint(CreateBallJoint(link->getRB(), above, kWreckPivot + down * (kWreckPitch * float(i))));
        above = link->getRB();
    }
    world.name(world.bodies().front(), "top");
    const float reach = kWreckPitch * float(kWreckLinks);
    iPhysicsFrame* ball =
        world.name(world.sphere(kWreckPivot + down * (reach + kWreckRadius), kWreckRadius, 500.0f), "ball");
    world.joint(CreateBallJoint(ball->getRB(), above, kWreckPivot + down * reach));
    // The wall, standing on the floor across the bottom of the swing (the ball passes 1.2 to 2.0 m up).
    const float side = 0.25f;
    for (int layer = 0; layer < 5; ++layer)
        for (int column = -2; column <= 2; ++column)
            world.box(Vector(0, side + 2 * side * float(layer), 2 * side * float(column)),
                      Vector(side, side, side), 10.0f);
}

void buildCloth(World& world) {
    world.ground();
    iPhysicsFrame* ball = world.name(world.sphere(Vector(0, 1.0f, 0), 0.5f, 1.0f), "sphere");
    ball->getDynamics()->physicsType = PHYS_FixedInSpace;
    // 10 x 10 bodies 0.15 m apart, level, 0.4 m above the sphere's top. Each has a sphere of 0.4 times the
    // spacing: bodies no spring joins collide, so the cloth does not pass through itself where it folds.
    constexpr int n = 10;
    const float spacing = 0.15f, half = 0.5f * spacing * float(n - 1);
    std::array<bool, n * n> mask;
    mask.fill(true);
    iSoftBody* cloth =
        world.softBody(CreateSoftBody(mask.data(), n, n, Vector(-half, 1.9f, -half), Vector(spacing, 0, 0),
                                      Vector(0, 0, spacing), 0.02f, 200.0f, 0.2f),
                       0.4f * spacing);
    // Cloth does not roll: its bodies' turning is locked (a zero inverse inertia), so that they slide on the
    // sphere under friction instead of rolling off it like ball bearings.
    for (int i = 0; cloth && i < cloth->getBodyCount(); ++i)
        cloth->getBody(i)->getDynamics().setInverseInertiaTensor(Matrix(0.0f));
}

void buildSoftBlob(World& world) {
    world.ground();
    // A disc of 11 places across (0.8 m), tilted 30 degrees from level about x, its lowest body 0.5 m above
    // the floor: it lands on its edge and flops flat (upright, it would roll away like a wheel).
    constexpr int n = 11;
    const float spacing = 0.08f, centre = 0.5f * float(n - 1), tilt = 0.5236f;
    std::array<bool, n * n> mask;
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const float dc = float(c) - centre, dr = float(r) - centre;
            mask[size_t(r * n + c)] = dc * dc + dr * dr <= (centre + 0.2f) * (centre + 0.2f);
        }
    // Jelly: well damped (each spring at about half its critical damping, 2 sqrt(k m) = 20 N s/m).
    const Vector across(spacing, 0, 0), up(0, spacing * std::sin(tilt), spacing * std::cos(tilt));
    world.softBody(CreateSoftBody(mask.data(), n, n, Vector(-centre * spacing, 0.5f, -centre * up.z), across,
                                  up, 0.05f, 2000.0f, 10.0f),
                   0.5f * spacing);
}

void addJointScenes(std::deque<SceneSpec>& scenes) {
    const SceneSpec joints[] = {
        {"cradle-strings", "Newton's cradle of 5 balls on strings, 1 released (named: cue, last)",
         [](World& w) { buildStringCradle(w, 1); }, nullptr},
        {"cradle-strings-2", "Newton's cradle of 5 balls on strings, 2 released (named: cue, last)",
         [](World& w) { buildStringCradle(w, 2); }, nullptr},
        {"cradle-strings-3", "Newton's cradle of 5 balls on strings, 3 released (named: cue, last)",
         [](World& w) { buildStringCradle(w, 3); }, nullptr},
        {"hinge-chain", "20 box links on hinges hanging from the world, kicked (named: top, bottom)",
         [](World& w) { buildHingeChain(w, 20); }, nullptr},
        {"door", "a door on a limited, motorised hinge, a ball thrown at it (named: door, ball)", buildDoor,
         throwAtDoor},
        {"ragdoll", "a ragdoll of 10 boxes on ball joints and hinges dropped (named: torso, head)",
         buildRagdoll, nullptr},
        {"rope-bridge", "a rope pinned at both ends, a box dropped on it (named: box)", buildRopeBridge,
         dropOnBridge},
        {"wrecking-ball", "a 500 kg ball on a light chain swung through a wall of boxes (named: ball, top)",
         buildWreckingBall, nullptr},
        {"cloth", "a soft body cloth dropped on a fixed sphere (named: sphere)", buildCloth, nullptr},
        {"soft-blob", "a round soft body dropped tilted on the floor", buildSoftBlob, nullptr},
    };
    for (const SceneSpec& s : joints) scenes.push_back(s);
}
