// RecordingWriter.h - the reference game's --record FILE: every frame of a run written down (each body's
// pose, velocities and shape, the frame's contacts and HitWall calls), so that --replay (Replay.h) can print
// the run's summary and draw its pictures without the physics engine.
//
// Format, version 1: plain text, one record per line, fields separated by single spaces. Floats are written
// as the shortest decimal that reads back to the very same float (bits; std::to_chars, e.g. 1.01, -0.5,
// 3e-07): a replay redraws the pictures exactly. Vectors are three floats x y z; "rot" is the 3x3 rotation,
// rows r1 r2 r3 (row i = the body's local axis i in world space, row-vector convention as Matrix).
//   guardian-recording 1                  the first line: format and version
//   scene NAME                            the scene's name (Scenes.h)
//   bodies N                              bodies at the start; their shape lines follow
//   shape plane N_VECTOR OFFSET           a bodiless plane: unit normal, offset along it (World::ground)
//   shape sphere BODY MASS RADIUS         body number BODY (0, 1, ... in order) is a sphere...
//   shape box BODY MASS HALF_EXTENTS      ... or a box; MASS in kg as built
// Shape lines come in the order the world built them (the order its space holds and draws them). A body a
// scene adds later (a shot) gets its shape line just before the first frame that has it. Then per frame:
//   frame F TIME_MS STEPS OVERLAP BODIES CONTACTS EVENTS
//       F counts from 0 (the scene as built, before any update) by one; TIME_MS is the game clock since
//       the start; STEPS physics steps taken so far; OVERLAP the deepest overlap the solver left (m); then
//       how many bodies, contacts and events the frame has. Their lines follow in that order.
//   b STATE ORIGIN rot VELOCITY ANGULAR_VELOCITY ANGULAR_MOMENTUM     one per body, in body order
//       STATE: A awake, S asleep, F fixed in space, Z fixed and marked asleep; ORIGIN the body frame's origin
//       (World's bodies have their centre of mass there); velocities in m/s and rad/s, angular momentum in kg
//       m^2/s (world axes).
//   b =                                   the body's line is the same as in the previous frame
//   c POINT NORMAL DEPTH                  a contact of the space's list (the normal points at its g2)
//   c =                                   instead of all CONTACTS lines: the same as the previous frame's
//   h BODY OTHER NORMAL POINT             a HitWall call this frame: the listening body, the one it hit (-1:
//                                         a plane), the hit normal (towards OTHER) and point
//   h =                                   instead of all EVENTS lines: the same as the previous frame's
// and last:
//   end FRAMES OK                         the run's last frame number and verdict, or
//   end FRAMES FAIL REASON...             (REASON: the rest of the line)
// A file without its end line is truncated.
#pragma once

#include "iCollisionListener.h"

#include <cstdio>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

class World;
class iRigidBody;

class RecordingWriter {
public:
    RecordingWriter() = default;
    RecordingWriter(const RecordingWriter&) = delete;
    RecordingWriter& operator=(const RecordingWriter&) = delete;
    ~RecordingWriter(); // closes the file; listeners stay valid until then (attached bodies die first)

    // Opens (truncates) path for writing; false when it cannot.
    bool open(const std::string& path);
    // The header, for world as scene built it; listens to its bodies' HitWall calls from now on.
    void begin(const World& world, const char* scene);
    // One frame: the shapes of bodies added since the last call, then the frame's records.
    void frame(const World& world, int frame, int timeMs, long long steps, float overlap);
    // The last line: the last frame's number and the verdict (failure nullptr: OK). Flushes.
    void end(const char* failure);

private:
    struct Listener final : iCollisionListener {
        RecordingWriter* writer = nullptr;
        int body = 0;
        void HitWall(iRigidBody* other, Vector normal, Vector point) override;
    };
    void defineShapes(const World& world);
    // Writes block, or same when it is the previous frame's (last); block becomes last.
    void writeBlock(std::string& block, std::string& last, const char* same);

    std::FILE* m_file = nullptr;
    size_t m_shapesWritten = 0;
    std::vector<std::unique_ptr<Listener>> m_listeners; // one per body, in body order
    std::unordered_map<const iRigidBody*, int> m_index; // each body's number
    std::vector<std::string> m_lastLine;                // each body's previous "b" line
    std::string m_events;                               // this frame's "h" lines so far
    std::string m_lastContacts, m_lastEvents;           // the previous frame's "c" and "h" lines
    size_t m_eventCount = 0;
    int m_lastFrame = 0;
};
