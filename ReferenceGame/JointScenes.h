// JointScenes.h - the demo scenes built with joints (a cradle on strings, a hinge chain, a motorised door,
// a ragdoll, a rope bridge, a wrecking ball, cloth, a soft blob), registered with the built-in scenes
// (Scenes.cpp) and used by the game tests. Sizes in metres, masses in kilograms; y is up and the floor is at
// y = 0. The World keeps every joint, rope and soft body made here and deletes it with the scene.
#pragma once

#include "MathDeclarations.h"
#include "Scenes.h"

#include <deque>

// Newton's cradle on strings: five balls (restitution 1, no friction), each hung from the world by two
// strings in a V (distance joints that go slack but do not stretch) so it swings in the x-y plane only, 1 mm
// apart; the first `released` balls (1..4) swung out on their strings to kCradleRaise above the others.
// Named: cue (the first ball), last.
void buildStringCradle(World& world, int released);
const float kCradleRaise = 0.3f;

// `links` box links on hinges (axis z) hanging from the world at (0, 5, 0), the bottom one kicked sideways.
// Named: top, bottom.
void buildHingeChain(World& world, int links);

// A door (a box) hinged to the world about a vertical axis, its hinge angle limited to
// [kDoorClosed, kDoorOpen] and a motor driving it open at kDoorMotorSpeed; at frame kDoorThrowFrame a ball
// is thrown at it, pushing it further open against its stop. Named: door, ball.
void buildDoor(World& world);
void throwAtDoor(World& world, int frame); // the door scene's act
const float kDoorClosed = 0.0f, kDoorOpen = 1.4f, kDoorMotorSpeed = 1.0f, kDoorMotorTorque = 40.0f;
const int kDoorThrowFrame = 150;

// A ragdoll of boxes (torso, head, upper and lower arms and legs) on ball joints (shoulders, hips, neck:
// cone and twist limits) and hinges (elbows, knees: limits), dropped tilted onto the floor. Named: torso,
// head.
void buildRagdoll(World& world);

// A rope (iRope) of 30 segments, 6.3 m long, hanging between two pins to the world 6 m apart; at frame
// kBridgeDropFrame a box is dropped on its middle. Named: box.
void buildRopeBridge(World& world);
void dropOnBridge(World& world, int frame); // the rope bridge's act
const int kBridgeDropFrame = 60;

// A wrecking ball: a 500 kg sphere (0.4 m) on ten 0.5 kg box links (0.4 m, ball joints) from a pivot in the
// world kWreckPivot, let go pulled out kWreckAngle toward -x; at the bottom of its swing it goes through a
// wall of 25 boxes (0.5 m, 10 kg: five columns along z, five layers) standing across x = 0. Its links are a
// thousandth of its mass: the chain holds it by tethers (Physics/JointTethers.cpp). Named: ball, top.
void buildWreckingBall(World& world);
const Vector kWreckPivot(0, 6, 0);
const float kWreckAngle = 1.0472f, kWreckPitch = 0.4f, kWreckRadius = 0.4f; // 60 degrees; m; m
const int kWreckLinks = 10, kWreckWallBoxes = 25;

// A soft body (iSoftBody, a full 10 x 10 mask) level above a fixed sphere, dropped on it to drape. Named:
// sphere.
void buildCloth(World& world);

// A soft body from a round mask (a disc of 0.8 m) dropped tilted on the floor.
void buildSoftBlob(World& world);

// Appends the joint scenes to the built-in list (Scenes.cpp's registry).
void addJointScenes(std::deque<SceneSpec>& scenes);
