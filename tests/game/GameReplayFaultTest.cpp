// GameReplayFaultTest.cpp - --replay of files that are not whole, well-formed recordings: a recording cut
// at every byte, damaged lines of every kind, garbage and a missing file are each refused with
// RUN_BAD_ARGUMENTS (exit status 2) and a message naming the file, its line and the fault; none crashes.
#include "GameTestSupport.h"

#include "Replay.h"

#include <functional>

using namespace game_test;

namespace {

std::vector<std::string> recLines(const std::string& text) {
    std::vector<std::string> lines;
    std::stringstream ss(text);
    for (std::string line; std::getline(ss, line);) lines.push_back(line);
    return lines;
}

std::string recJoin(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    return text;
}

void recWrite(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// Replays path; returns the status and puts what was said on stderr into err.
RunStatus recReplay(const std::string& path, std::string& err) {
    GameOptions o;
    o.replay = path;
    o.out = std::tmpfile();
    o.err = std::tmpfile();
    const RunStatus status = replayRecording(o);
    err = readBack(o.err);
    std::fclose(o.out);
    std::fclose(o.err);
    return status;
}

// The index of the n-th line (from 0) that starts with prefix.
size_t recFind(const std::vector<std::string>& lines, const std::string& prefix, int n = 0) {
    for (size_t i = 0; i < lines.size(); ++i)
        if (lines[i].rfind(prefix, 0) == 0 && n-- == 0) return i;
    ADD_FAILURE() << "no line " << prefix;
    return 0;
}

// A whole recording of the drop scene: 20 frames of a falling ball.
std::string recDropRecording(const std::string& path) {
    GameOptions o;
    o.frames = 20;
    o.record = path;
    o.out = std::tmpfile();
    EXPECT_EQ(runScene(dropScene(), o), RUN_OK);
    std::fclose(o.out);
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

TEST(GameReplayFaults, ARecordingCutAnywhereIsRefusedAsTruncated) {
    const std::string path = scratch("cut.rec");
    const std::string whole = recDropRecording(path);
    std::string err;
    ASSERT_EQ(recReplay(path, err), RUN_OK) << err;
    EXPECT_EQ(err, "");
    // Every cut but the last newline's (the end line is whole without it) loses something: each cut in the
    // header and the first frames, then every 29th byte.
    for (size_t cut = 0; cut + 1 < whole.size(); cut += cut < 600 ? 1 : 29) {
        recWrite(path, whole.substr(0, cut));
        ASSERT_EQ(recReplay(path, err), RUN_BAD_ARGUMENTS) << "cut at byte " << cut;
        ASSERT_EQ(err.rfind("ReferenceGame: --replay: " + path + ":", 0), 0u) << err;
    }
    // Cut after a frame line: its body line is missing.
    const size_t frame10 = whole.find("\nframe 10 ");
    recWrite(path, whole.substr(0, whole.find('\n', frame10 + 1) + 1));
    recReplay(path, err);
    EXPECT_NE(err.find(": truncated in frame 10"), std::string::npos) << err;
    // Cut after a whole frame: no end line.
    recWrite(path, whole.substr(0, frame10 + 1));
    recReplay(path, err);
    EXPECT_NE(err.find(": truncated: no end line"), std::string::npos) << err;
    std::remove(path.c_str());
}

TEST(GameReplayFaults, DamagedLinesAreRefusedWithTheirLineAndFault) {
    const std::string path = scratch("bad.rec");
    const std::vector<std::string> whole = recLines(recDropRecording(path));
    struct Damage {
        const char* what;
        std::function<void(std::vector<std::string>&)> edit;
        const char* message;
    };
    const std::vector<Damage> damages = {
        {"another format", [](auto& l) { l[0] = "hello"; }, ":1: not a guardian recording"},
        {"a newer version", [](auto& l) { l[0] = "guardian-recording 2"; },
         ":1: format version not supported"},
        {"no scene", [](auto& l) { l[1] = "scene"; }, ":2: want \"scene NAME\""},
        {"a scene that is a path", [](auto& l) { l[1] = "scene ../x"; }, ":2: want \"scene NAME\""},
        {"more bodies than shapes", [](auto& l) { l[2] = "bodies 2"; },
         "the header says 2 bodies but 1 have"},
        {"a shape for the wrong body",
         [](auto& l) { l[recFind(l, "shape sphere")] = "shape sphere 3 2 0.5"; },
         "a shape for body 3 where body 0 comes next"},
        {"a number that is not one", [](auto& l) { l[recFind(l, "b A", 5)].replace(4, 1, "x"); },
         "bad body line (body 0 in frame "},
        {"a NaN", [](auto& l) { l[recFind(l, "b A", 5)] = "b A nan" + l[recFind(l, "b A", 5)].substr(5); },
         "bad body line"},
        {"a state that is none", [](auto& l) { l[recFind(l, "b A", 3)][2] = 'Q'; }, "bad body line"},
        {"a body line too short", [](auto& l) { l[recFind(l, "b A", 3)] = "b A 1 2 3"; }, "bad body line"},
        {"a frame skipped", [](auto& l) { l[recFind(l, "frame 5 ")].replace(6, 1, "6"); },
         "frame 6 after frame 4"},
        {"a frame with two bodies", [](auto& l) { l[recFind(l, "frame 2 ")] = "frame 2 32 1 0 2 0 0"; },
         "frame 2 has 2 bodies but 1 have shapes"},
        {"a frame that promises an event",
         [](auto& l) { l[recFind(l, "frame 2 ")] = "frame 2 32 1 0 1 0 1"; }, "bad event line in frame 2"},
        {"an event of a body that is none",
         [](auto& l) {
             const size_t at = recFind(l, "frame 2 ");
             l[at] = "frame 2 32 1 0 1 0 1";
             l.insert(l.begin() + long(at) + 2, "h 7 -1 0 1 0 0 0 0");
         },
         "bad event line in frame 2"},
        {"\"b =\" with nothing before", [](auto& l) { l[recFind(l, "b A")] = "b ="; }, "\"b =\" for body 0"},
        {"a contact line cut short",
         [](auto& l) {
             const size_t at = recFind(l, "frame 2 ");
             l[at] = "frame 2 32 1 0 1 1 0";
             l.insert(l.begin() + long(at) + 2, "c 0 0 0 0 1");
         },
         "bad contact line in frame 2"},
        {"an unknown line", [](auto& l) { l[recFind(l, "frame 3 ")] = "fram 3"; },
         "want a frame, shape or end"},
        {"a wrong last frame", [](auto& l) { l.back() = "end 19 OK"; },
         "the end line says frame 19 was the last"},
        {"a bad verdict", [](auto& l) { l.back() = "end 20 MAYBE"; }, "bad end line"},
        {"a failure with no reason", [](auto& l) { l.back() = "end 20 FAIL"; }, "bad end line"},
        {"more after the end", [](auto& l) { l.push_back("frame 21 336 21 0 1 0 0"); }, "more after the end"},
        {"no frame at all", [](auto& l) { l.erase(l.begin() + 5, l.end() - 1); }, "no frame before the end"},
    };
    std::string err;
    for (const Damage& d : damages) {
        std::vector<std::string> lines = whole;
        d.edit(lines);
        recWrite(path, recJoin(lines));
        EXPECT_EQ(recReplay(path, err), RUN_BAD_ARGUMENTS) << d.what;
        EXPECT_NE(err.find(d.message), std::string::npos) << d.what << ": " << err;
        EXPECT_EQ(err.rfind("ReferenceGame: --replay: " + path + ":", 0), 0u) << d.what << ": " << err;
    }
    std::string garbage;
    for (int i = 0; i < 4096; ++i) garbage += char((i * 7919) & 0xFF);
    recWrite(path, garbage);
    EXPECT_EQ(recReplay(path, err), RUN_BAD_ARGUMENTS);
    EXPECT_NE(err.find(":1: not a guardian recording"), std::string::npos) << err;
    std::remove(path.c_str());
    EXPECT_EQ(recReplay(path, err), RUN_BAD_ARGUMENTS);
    EXPECT_EQ(err, "ReferenceGame: --replay: cannot read " + path + "\n");
}
