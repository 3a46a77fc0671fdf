// SpaceEntry.h - a collision space's working state for one member geometry (SimpleCollisionSpace::Entry): its
// pose, box and filter as the last call gathered them, and what they were made from, so a call where little
// changed reads little (SpaceGather.cpp). The broadphases read its box, activity and plane flag.
#pragma once

#include "CollisionGeometry.h"
#include "PoseInputs.h"
#include "Shapes.h"

#include <cstdint>

class iRigidBody;

// One per member, in the members' order (m_entries[i] is m_members[i]'s, and SpaceState::entry names it),
// kept between calls: a geometry whose pose, shapes and body did not change since the last call keeps its
// shapes and box (SpaceGather.cpp, gatherEntry). Laid out for the call where little changed: what every call
// reads comes first, in three cache lines; the pose and the previous pose only when the body moved.
struct alignas(64) SpaceEntry {
    CollisionGeometry* g = nullptr;
    iRigidBody* body = nullptr;
    bool active = true; // gathered this call; an inactive one (no body, a pose not finite) is in no pair
    bool fixed = false, plane = false, moved = false; // fixed: resting and not moved since last call
    bool sensor = false;
    bool disturbed = false; // moved, reshaped or given another body since the last call
    bool newcomer = false;  // in the space (with this body) since the last call only
    bool asleep = false;    // its body (or its root) sleeps
    unsigned teleports = 0; // RBDynamics::teleports of the body and its root
    std::uint32_t layer = 1, mask = ~std::uint32_t(0); // its collision filter (iCollisionFilter.h)
    float motion = 0.0f;   // upper bound on how far any point of it moved since the previous call
    float rotAngle = 0.0f; // rotation since the previous call (radians)
    float minDim = 0.0f;   // smallest dimension of its shapes
    gcol::Aabb box;        // swept over the motion when moved
    // What the shapes and boxes were made from (the space's; a broadphase ignores it).
    struct Cache {
        const RBDynamics* dynamics = nullptr; // its body's at the last call (to fetch ahead; rootIsSelf)
        bool valid = false;       // shapes, tight, minDim and bound hold for origin, rotation, version, body
        bool raw = false;         // the body had no parent: its pose came from rawInputs
        bool prevIsPose = false;  // SpaceState::previous* were last written from origin and rotation
        bool prevCurrent = false; // this call: SpaceState::previous* hold origin and rotation already
        bool prevIsSelf = false;  // prevOrigin and prevRotation are origin and rotation, bit for bit
        bool selfAngleKnown = false;
        bool sized = false;      // minDim and bound hold for sizedVersion
        bool reposed = false;    // its shapes were made anew at the last call (so probably at this one)
        bool rootIsSelf = false; // dynamics had no parent at the last call
        // The geometry as the last call left it, so that a call need not read it (gatherEntry): its
        // filter, body and shape version are the entry's (no CollisionGeometry::edited() since), and its
        // space state's hasPrevious, previousBody == body and previousTeleports are these.
        bool mirrored = false;
        bool hadPrevious = false, previousIsBody = false;
        unsigned previousTeleports = 0;
        unsigned shapeVersion = 0;
        float bound = 0.0f, selfAngle = 0.0f; // bounding radius; rotationAngle(rotation, rotation)
        // A call where nothing moved reads the entry up to here: its first three cache lines.
        gcol::PoseInputs rawInputs;
        gcol::Aabb tight; // its shapes' box at the pose
        unsigned sizedVersion = 0;
        bool centred = false; // its one shape sits at the body's origin (centredOnBody), for sizedVersion
        int capacity = 0;     // shapes m_shapes holds for it from first on
    } cache;
    int first = 0, last = 0;   // its shapes in m_shapes
    Vector origin, prevOrigin; // the previous pose: set (and read) only in a call with sampling on
    Matrix rotation = Matrix(1), prevRotation = Matrix(1);
};
