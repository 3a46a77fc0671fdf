// RecordingReader.h - reading a --record file (its format: RecordingWriter.h) back, a frame at a time, and
// refusing with a message naming the line whatever is not a whole, well-formed recording.
#pragma once

#include "MathDeclarations.h"

#include <fstream>
#include <string>
#include <vector>

struct RecordedShape {
    enum Kind { Sphere, Box, Plane } kind;
    int body;     // -1 for a plane
    float mass;   // kg (bodies)
    Vector size;  // Sphere: (r, r, r); Box: half extents; Plane: the unit normal
    float offset; // Plane only
};

struct RecordedBody {
    char state; // 'A' awake, 'S' asleep, 'F' fixed in space, 'Z' fixed and marked asleep
    bool fixed() const { return state == 'F' || state == 'Z'; }
    bool asleep() const { return state == 'S' || state == 'Z'; }
    Vector origin;
    Matrix rotation; // rows: the body's local axes in world space (m44 = 1)
    Vector velocity, angularVelocity, angularMomentum;
};

struct RecordedContact {
    Vector point, normal;
    float depth;
};

struct RecordedEvent {
    int body, other; // other -1: a plane
    Vector normal, point;
};

struct RecordedFrame {
    int frame = -1, timeMs = 0;
    long long steps = 0;
    float overlap = 0;
    std::vector<RecordedBody> bodies; // in body order
    std::vector<RecordedContact> contacts;
    std::vector<RecordedEvent> events;
};

class RecordingReader {
public:
    // Opens path and reads the header; false (error() says why) when it cannot.
    bool open(const std::string& path);
    // Reads the next frame into f (the shapes of bodies it adds go to shapes()); false at the end line (then
    // error() is empty) or on a fault (error() says which line and what).
    bool next(RecordedFrame& f);
    // After next() returned a frame: whether it is the recording's last (the end line follows).
    bool lastFrame() const { return m_endSeen; }

    const std::string& scene() const { return m_scene; }
    size_t initialBodies() const { return m_initialBodies; }
    const std::vector<RecordedShape>& shapes() const { return m_shapes; } // as built, planes included
    size_t bodies() const { return m_bodies; }                            // defined so far
    const std::string& verdict() const { return m_verdict; } // "OK" or "FAIL reason", after the end line
    const std::string& error() const { return m_error; }

private:
    bool readLine(); // the next line into m_line (false at the end of the file)
    bool fail(const std::string& what);
    bool parseShape(const std::vector<std::string>& w);
    bool parseEnd(const std::vector<std::string>& w);
    bool sameAsBefore(char tag, size_t count, size_t before, bool& same, const std::string& inFrame);
    bool readContacts(std::vector<RecordedContact>& contacts, const std::string& inFrame);
    bool readEvents(std::vector<RecordedEvent>& events, const std::string& inFrame);

    std::ifstream m_in;
    std::string m_path, m_line, m_scene, m_verdict, m_error;
    long m_lineNo = 0;
    size_t m_initialBodies = 0, m_bodies = 0;
    std::vector<RecordedShape> m_shapes;
    std::vector<RecordedBody> m_previous;    // for "b ="
    std::vector<RecordedContact> m_contacts; // the previous frame's, for "c ="
    std::vector<RecordedEvent> m_events;     // ... and for "h ="
    int m_lastFrame = -1;
    bool m_haveLine = false, m_endSeen = false;
};
