// RecordingReader.cpp - parsing the text recording (RecordingWriter.h), checking every count, number and
// index as it goes: a replay of a damaged file stops at the first fault with its line, never guesses.
#include "RecordingReader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace {

std::vector<std::string> readerWords(const std::string& line) {
    std::vector<std::string> words;
    size_t start = 0;
    while (start <= line.size()) {
        size_t space = line.find(' ', start);
        if (space == std::string::npos) space = line.size();
        words.push_back(line.substr(start, space - start));
        start = space + 1;
    }
    return words;
}

bool readerFloat(const std::string& word, float& out) {
    if (word.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtof(word.c_str(), &end);
    return *end == '\0' && errno == 0 && std::isfinite(out);
}

bool readerInt(const std::string& word, long long lo, long long hi, long long& out) {
    if (word.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtoll(word.c_str(), &end, 10);
    return *end == '\0' && errno == 0 && out >= lo && out <= hi;
}

// count floats from words[first], into out; false when one is not a finite number.
bool readerFloats(const std::vector<std::string>& w, size_t first, size_t count, float* out) {
    for (size_t i = 0; i < count; ++i)
        if (!readerFloat(w[first + i], out[i])) return false;
    return true;
}

bool readerVector(const std::vector<std::string>& w, size_t first, Vector& v) {
    float f[3];
    if (!readerFloats(w, first, 3, f)) return false;
    v = Vector(f[0], f[1], f[2]);
    return true;
}

const long long kReaderMaxCount =
    100000000; // bodies, contacts or events in a frame: anything beyond is corrupt

} // namespace

bool RecordingReader::fail(const std::string& what) {
    m_error = m_path + ":" + std::to_string(m_lineNo) + ": " + what;
    return false;
}

bool RecordingReader::readLine() {
    if (!std::getline(m_in, m_line)) return false;
    ++m_lineNo;
    return true;
}

bool RecordingReader::open(const std::string& path) {
    m_path = path;
    m_in.open(path, std::ios::binary);
    if (!m_in) {
        m_error = "cannot read " + path;
        return false;
    }
    if (!readLine() || m_line.rfind("guardian-recording ", 0) != 0) return fail("not a guardian recording");
    if (m_line != "guardian-recording 1") return fail("format version not supported (this game reads 1)");
    std::vector<std::string> w;
    if (!readLine() || (w = readerWords(m_line)).size() != 2 || w[0] != "scene" || w[1].empty() ||
        w[1].find('/') != std::string::npos) // the name goes into picture file names
        return fail("want \"scene NAME\"");
    m_scene = w[1];
    long long n = 0;
    if (!readLine() || (w = readerWords(m_line)).size() != 2 || w[0] != "bodies" ||
        !readerInt(w[1], 0, kReaderMaxCount, n))
        return fail("want \"bodies N\"");
    m_initialBodies = size_t(n);
    while (readLine() && m_line.rfind("shape ", 0) == 0)
        if (!parseShape(readerWords(m_line))) return false;
    if (m_bodies != m_initialBodies)
        return fail("the header says " + std::to_string(m_initialBodies) + " bodies but " +
                    std::to_string(m_bodies) + " have shapes");
    m_haveLine = bool(m_in);
    if (!m_haveLine) return fail("truncated: no frame");
    return true;
}

bool RecordingReader::parseShape(const std::vector<std::string>& w) {
    RecordedShape s{RecordedShape::Plane, -1, 0.0f, Vector(), 0.0f};
    if (w.size() == 6 && w[1] == "plane") {
        if (!readerVector(w, 2, s.size) || !readerFloat(w[5], s.offset)) return fail("bad plane shape");
    } else if ((w.size() == 5 && w[1] == "sphere") || (w.size() == 7 && w[1] == "box")) {
        s.kind = w[1] == "box" ? RecordedShape::Box : RecordedShape::Sphere;
        long long body = 0;
        if (!readerInt(w[2], 0, kReaderMaxCount, body) || size_t(body) != m_bodies)
            return fail("a shape for body " + w[2] + " where body " + std::to_string(m_bodies) +
                        " comes next");
        s.body = int(body);
        float r = 0;
        if (!readerFloat(w[3], s.mass) ||
            (s.kind == RecordedShape::Box ? !readerVector(w, 4, s.size) : !readerFloat(w[4], r)))
            return fail("bad " + w[1] + " shape");
        if (s.kind == RecordedShape::Sphere) s.size = Vector(r, r, r);
        ++m_bodies;
    } else {
        return fail("bad shape line");
    }
    m_shapes.push_back(s);
    return true;
}

bool RecordingReader::parseEnd(const std::vector<std::string>& w) {
    long long frames = 0;
    if (w.size() < 3 || !readerInt(w[1], 0, kReaderMaxCount, frames) || (w[2] != "OK" && w[2] != "FAIL") ||
        (w[2] == "OK" ? w.size() != 3 : w.size() < 4))
        return fail("bad end line");
    if (frames != m_lastFrame)
        return fail("the end line says frame " + w[1] + " was the last, but it was " +
                    std::to_string(m_lastFrame));
    m_verdict = m_line.substr(m_line.find(w[2]));
    if (readLine()) return fail("more after the end line");
    return true;
}

// A block of count lines, or "X =" (the previous frame's block, as many): true when it was the latter.
bool RecordingReader::sameAsBefore(char tag, size_t count, size_t before, bool& same,
                                   const std::string& inFrame) {
    same = false;
    if (count == 0) return true;
    if (!readLine()) return fail("truncated" + inFrame);
    if (m_line.size() != 3 || m_line[0] != tag || m_line.compare(1, 2, " =") != 0) return true;
    if (before != count)
        return fail(std::string(1, tag) + " = with " + std::to_string(count) +
                    " lines where the frame before had " + std::to_string(before) + inFrame);
    same = true;
    return true;
}

bool RecordingReader::readContacts(std::vector<RecordedContact>& contacts, const std::string& inFrame) {
    const size_t count = contacts.size();
    contacts.swap(m_contacts);
    bool same = false;
    if (!sameAsBefore('c', count, contacts.size(), same, inFrame)) return false;
    if (same) {
        m_contacts = contacts;
        return true;
    }
    contacts.resize(count);
    for (size_t i = 0; i < count; ++i) {
        std::vector<std::string> x;
        RecordedContact& c = contacts[i];
        if (i > 0 && !readLine()) return fail("truncated" + inFrame);
        if ((x = readerWords(m_line)).size() != 8 || x[0] != "c" || !readerVector(x, 1, c.point) ||
            !readerVector(x, 4, c.normal) || !readerFloat(x[7], c.depth))
            return fail("bad contact line" + inFrame);
    }
    m_contacts = contacts;
    return true;
}

bool RecordingReader::readEvents(std::vector<RecordedEvent>& events, const std::string& inFrame) {
    const size_t count = events.size();
    events.swap(m_events);
    bool same = false;
    if (!sameAsBefore('h', count, events.size(), same, inFrame)) return false;
    if (same) {
        m_events = events;
        return true;
    }
    events.resize(count);
    const long long bodies = (long long)m_bodies;
    for (size_t i = 0; i < count; ++i) {
        std::vector<std::string> x;
        RecordedEvent& e = events[i];
        long long body = 0, other = 0;
        if (i > 0 && !readLine()) return fail("truncated" + inFrame);
        if ((x = readerWords(m_line)).size() != 9 || x[0] != "h" || !readerInt(x[1], 0, bodies - 1, body) ||
            !readerInt(x[2], -1, bodies - 1, other) || !readerVector(x, 3, e.normal) ||
            !readerVector(x, 6, e.point))
            return fail("bad event line" + inFrame);
        e.body = int(body);
        e.other = int(other);
    }
    m_events = events;
    return true;
}

bool RecordingReader::next(RecordedFrame& f) {
    for (;;) {
        if (!m_haveLine) return fail(m_lastFrame < 0 ? "truncated: no frame" : "truncated: no end line");
        m_haveLine = false;
        const std::vector<std::string> w = readerWords(m_line);
        if (w[0] == "shape") {
            if (!parseShape(w)) return false;
            m_haveLine = readLine();
            continue;
        }
        if (w[0] == "end") {
            if (m_lastFrame < 0) return fail("no frame before the end line");
            parseEnd(w);
            return false;
        }
        long long n[7];
        if (w.size() != 8 || w[0] != "frame") return fail("want a frame, shape or end line");
        const long long limits[7][2] = {
            {0, kReaderMaxCount}, {0, 1LL << 31},       {0, 1LL << 62},      {0, 0},
            {0, kReaderMaxCount}, {0, kReaderMaxCount}, {0, kReaderMaxCount}};
        for (int i = 0; i < 7; ++i)
            if (i != 3 && !readerInt(w[size_t(i) + 1], limits[i][0], limits[i][1], n[i]))
                return fail("bad frame line");
        if (!readerFloat(w[4], f.overlap)) return fail("bad frame line");
        if (n[0] != m_lastFrame + 1)
            return fail("frame " + w[1] + " after frame " + std::to_string(m_lastFrame));
        if (size_t(n[4]) != m_bodies)
            return fail("frame " + w[1] + " has " + w[5] + " bodies but " + std::to_string(m_bodies) +
                        " have shapes");
        f.frame = int(n[0]);
        f.timeMs = int(n[1]);
        f.steps = n[2];
        f.bodies.resize(size_t(n[4]));
        f.contacts.resize(size_t(n[5]));
        f.events.resize(size_t(n[6]));
        m_previous.resize(f.bodies.size(),
                          RecordedBody{'?', Vector(), Matrix(1), Vector(), Vector(), Vector()});
        const std::string inFrame = " in frame " + w[1];
        for (size_t i = 0; i < f.bodies.size(); ++i) {
            if (!readLine()) return fail("truncated" + inFrame);
            const std::vector<std::string> b = readerWords(m_line);
            RecordedBody& body = f.bodies[i];
            if (b.size() == 2 && b[0] == "b" && b[1] == "=") {
                if (m_previous[i].state == '?')
                    return fail("\"b =\" for body " + std::to_string(i) + ", new");
                body = m_previous[i];
                continue;
            }
            float r[9];
            if (b.size() != 23 || b[0] != "b" || b[1].size() != 1 || std::string("ASFZ").find(b[1][0]) > 3 ||
                !readerVector(b, 2, body.origin) || !readerFloats(b, 5, 9, r) ||
                !readerVector(b, 14, body.velocity) || !readerVector(b, 17, body.angularVelocity) ||
                !readerVector(b, 20, body.angularMomentum))
                return fail("bad body line (body " + std::to_string(i) + inFrame + ")");
            body.state = b[1][0];
            body.rotation = Matrix(r[0], r[1], r[2], 0, r[3], r[4], r[5], 0, r[6], r[7], r[8], 0, 0, 0, 0, 1);
            m_previous[i] = body;
        }
        if (!readContacts(f.contacts, inFrame) || !readEvents(f.events, inFrame)) return false;
        m_lastFrame = f.frame;
        m_haveLine = readLine();
        m_endSeen = m_haveLine && m_line.rfind("end ", 0) == 0;
        return true;
    }
}
