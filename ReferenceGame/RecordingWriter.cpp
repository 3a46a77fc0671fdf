// RecordingWriter.cpp - writing a run as the text recording RecordingWriter.h describes.
#include "RecordingWriter.h"

#include "RBDynamics.h"
#include "World.h"
#include "iCollisionSpace.h"
#include "iPhysicsFrame.h"
#include "iRigidBody.h"

#include <charconv>
#include <initializer_list>

namespace {

// The shortest decimal that reads back as the same float (std::to_chars): the replay draws from exactly
// what was drawn live, and it is several times faster than printf.
void recordFloats(std::string& line, std::initializer_list<float> values) {
    char buffer[32];
    for (float v : values) {
        buffer[0] = ' ';
        const std::to_chars_result r = std::to_chars(buffer + 1, buffer + sizeof buffer, v);
        line.append(buffer, r.ptr);
    }
}

void recordVector(std::string& line, const Vector& v) { recordFloats(line, {v.x, v.y, v.z}); }

char recordState(const RBDynamics& d) {
    const RBDynamics& root = *d.attachmentRoot();
    if (root.physicsType == PHYS_FixedInSpace) return root.sleeping ? 'Z' : 'F'; // a game may set both
    return root.sleeping ? 'S' : 'A';
}

} // namespace

RecordingWriter::~RecordingWriter() {
    if (m_file) std::fclose(m_file);
}

bool RecordingWriter::open(const std::string& path) {
    m_file = std::fopen(path.c_str(), "w");
    return m_file != nullptr;
}

void RecordingWriter::begin(const World& world, const char* scene) {
    if (!m_file) return;
    std::fprintf(m_file, "guardian-recording 1\nscene %s\nbodies %zu\n", scene, world.bodies().size());
    defineShapes(world);
}

void RecordingWriter::defineShapes(const World& world) {
    const std::vector<World::Shape>& shapes = world.shapes();
    for (; m_shapesWritten < shapes.size(); ++m_shapesWritten) {
        const World::Shape& s = shapes[m_shapesWritten];
        std::string line = "shape ";
        if (s.kind == World::Shape::Plane) {
            line += "plane";
            recordVector(line, s.size);
            recordFloats(line, {s.offset});
        } else {
            line += s.kind == World::Shape::Sphere ? "sphere " : "box ";
            line += std::to_string(s.body);
            recordFloats(line, {world.bodies()[size_t(s.body)]->getDynamics()->mass});
            if (s.kind == World::Shape::Sphere)
                recordFloats(line, {s.size.x});
            else
                recordVector(line, s.size);
        }
        std::fprintf(m_file, "%s\n", line.c_str());
    }
    // Listen to the new bodies (in body order, so a listener's index is its body's).
    for (size_t i = m_listeners.size(); i < world.bodies().size(); ++i) {
        m_listeners.push_back(std::make_unique<Listener>());
        m_listeners.back()->writer = this;
        m_listeners.back()->body = int(i);
        world.bodies()[i]->getRB()->attachListener(m_listeners.back().get());
        m_index.emplace(world.bodies()[i]->getRB(), int(i));
    }
}

void RecordingWriter::Listener::HitWall(iRigidBody* other, Vector normal, Vector point) {
    auto it = writer->m_index.find(other);
    const int otherIndex = it == writer->m_index.end() ? -1 : it->second; // nullptr: a plane
    std::string line = "h " + std::to_string(body) + " " + std::to_string(otherIndex);
    recordVector(line, normal);
    recordVector(line, point);
    writer->m_events += line + "\n";
    ++writer->m_eventCount;
}

void RecordingWriter::frame(const World& world, int frame, int timeMs, long long steps, float overlap) {
    if (!m_file) return;
    m_lastFrame = frame;
    defineShapes(world);
    const iCollisionSpace* space = world.space();
    const size_t contacts = space->getNumContacts();
    std::string head =
        "frame " + std::to_string(frame) + " " + std::to_string(timeMs) + " " + std::to_string(steps);
    recordFloats(head, {overlap});
    std::fprintf(m_file, "%s %zu %zu %zu\n", head.c_str(), world.bodies().size(), contacts, m_eventCount);
    m_lastLine.resize(world.bodies().size());
    for (size_t i = 0; i < world.bodies().size(); ++i) {
        const RBDynamics& d = *world.bodies()[i]->getDynamics();
        const Matrix r = d.getWorldOrientation().rotation();
        std::string line = "b ";
        line += recordState(d);
        recordVector(line, d.getWorldOrigin());
        recordFloats(line, {r.m11, r.m12, r.m13, r.m21, r.m22, r.m23, r.m31, r.m32, r.m33});
        recordVector(line, d.velocity);
        recordVector(line, d.angularVelocity);
        recordVector(line, d.angularMomentum);
        // A body at rest writes the same line frame after frame: "b =" keeps a resting pile's file small.
        std::fputs(line == m_lastLine[i] ? "b =\n" : (line + "\n").c_str(), m_file);
        m_lastLine[i] = std::move(line);
    }
    const CollisionContact* c = space->getContactList();
    std::string block;
    for (size_t i = 0; i < contacts; ++i) {
        block += "c";
        recordVector(block, c[i].pos);
        recordVector(block, c[i].normal);
        recordFloats(block, {c[i].depth});
        block += "\n";
    }
    // A resting pile's contacts and HitWall calls repeat frame after frame: "c =" and "h =" say so.
    writeBlock(block, m_lastContacts, "c =\n");
    writeBlock(m_events, m_lastEvents, "h =\n");
    m_events.clear();
    m_eventCount = 0;
}

void RecordingWriter::writeBlock(std::string& block, std::string& last, const char* same) {
    std::fputs(!block.empty() && block == last ? same : block.c_str(), m_file);
    last.swap(block);
}

void RecordingWriter::end(const char* failure) {
    if (!m_file) return;
    if (failure)
        std::fprintf(m_file, "end %d FAIL %s\n", m_lastFrame, failure);
    else
        std::fprintf(m_file, "end %d OK\n", m_lastFrame);
    std::fflush(m_file);
}
