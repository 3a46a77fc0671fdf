// DebugDrawTest.cpp - what the space and the scene draw (iDebugDrawable.h) is the geometry they hold: a
// recording iDebugDraw that implements only lines and text (and records points) checks drawn edges against
// box corners computed here, sphere lines against the radius, a resting contact's normal, sleeping marks,
// and that each flag switches its part on and off alone.
#include "MathDefinitions.h"
#include "World.h"
#include "iCollisionSpace.h"
#include "iDebugDrawable.h"
#include "iOctreeCollisionSpace.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"
#include "iRigidBody.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <list>
#include <map>
#include <string>
#include <vector>

namespace debugdraw_test {

// Records lines, points and texts; spheres and boxes come through iDebugDraw's defaults as lines.
struct Recorder final : iDebugDraw {
    struct Line {
        Vector from, to;
        DebugColour colour;
    };
    struct Mark {
        Vector at;
        DebugColour colour;
        std::string text;
    };
    std::vector<Line> lines;
    std::vector<Mark> points, texts;
    void drawLine(const Vector& from, const Vector& to, DebugColour colour) override {
        lines.push_back({from, to, colour});
    }
    void drawText(const Vector& at, const char* text, DebugColour colour) override {
        texts.push_back({at, colour, text});
    }
    void drawPoint(const Vector& at, float, DebugColour colour) override {
        points.push_back({at, colour, ""});
    }
    std::vector<Line> linesOf(DebugColour colour) const {
        std::vector<Line> out;
        for (const Line& l : lines)
            if (l.colour == colour) out.push_back(l);
        return out;
    }
};

float distance(const Vector& a, const Vector& b) {
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

// A scene with a world (simple space unless given), its time base set.
struct Scene {
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    World* world;
    int steps = 0;
    explicit Scene(iCollisionSpace* space = nullptr) {
        scene->update(0);
        world = new World(scene, space);
    }
    ~Scene() {
        delete world;
        scene->Delete();
    }
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;
    void run(int n) {
        for (int i = 0; i < n; ++i) scene->update(int(std::ceil(++steps * 1000.0 / 60.0)));
    }
    Recorder draw(unsigned flags) const {
        Recorder r;
        debugDrawOf(scene)->debugDraw(r, flags);
        return r;
    }
    Recorder drawSpace(unsigned flags) const {
        Recorder r;
        debugDrawOf(world->space())->debugDraw(r, flags);
        return r;
    }
};

// A game's own space: the seed's interface only.
struct StandInSpace final : iCollisionSpace {
    std::list<iCollisionGeometry*> none;
    bool add(iCollisionGeometry*) override { return false; }
    void remove(iCollisionGeometry*) override {}
    const std::list<iCollisionGeometry*>& getAttachedGeometry() override { return none; }
    void populateContactList(float) override {}
    const CollisionContact* getContactList() const override { return nullptr; }
    size_t getNumContacts() const override { return 0; }
    void suspend() const override {}
    void release() const override {}
    void Delete() const override {}
};

TEST(DebugDraw, SpaceAndSceneCanDrawAndAGamesStandInCannot) {
    Scene s;
    EXPECT_NE(debugDrawOf(s.scene), nullptr);
    EXPECT_NE(debugDrawOf(s.world->space()), nullptr);
    iCollisionSpace* octree = CreateOctreeCollisionSpace();
    EXPECT_NE(debugDrawOf(octree), nullptr);
    octree->Delete();
    const StandInSpace standIn;
    EXPECT_EQ(debugDrawOf(static_cast<const iCollisionSpace*>(&standIn)), nullptr);
    EXPECT_EQ(debugDrawOf(static_cast<const iCollisionSpace*>(nullptr)), nullptr);
}

TEST(DebugDraw, BoxIsTwelveEdgesBetweenItsCorners) {
    Scene s;
    const Vector centre(1, 2, 3), half(0.5f, 1.0f, 1.5f);
    const Matrix r = rotate(Vector(1, 2, 3), 0.7f);
    s.world->box(centre, half, 1.0f, r);
    Recorder drawn = s.drawSpace(DEBUGDRAW_Shapes);
    // The corners, from the rotation's rows read element by element (not through Matrix::direction).
    std::vector<Vector> corners;
    for (int i = 0; i < 8; ++i) {
        const float l[3] = {i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y, i & 4 ? half.z : -half.z};
        Vector c = centre;
        for (int row = 0; row < 3; ++row) c += Vector(r(row, 0), r(row, 1), r(row, 2)) * l[row];
        corners.push_back(c);
    }
    auto cornerOf = [&](const Vector& p) {
        for (int i = 0; i < 8; ++i)
            if (distance(p, corners[size_t(i)]) < 1e-5f) return i;
        return -1;
    };
    ASSERT_EQ(drawn.lines.size(), 12u);
    std::map<std::pair<int, int>, int> edges;
    for (const Recorder::Line& l : drawn.lines) {
        const int a = cornerOf(l.from), b = cornerOf(l.to);
        ASSERT_GE(a, 0);
        ASSERT_GE(b, 0);
        const int differ = a ^ b; // an edge joins corners that differ along exactly one axis
        EXPECT_TRUE(differ == 1 || differ == 2 || differ == 4) << a << " " << b;
        ++edges[{std::min(a, b), std::max(a, b)}];
        EXPECT_EQ(l.colour, debugcolour::kShape);
    }
    EXPECT_EQ(edges.size(), 12u); // each edge once
}

TEST(DebugDraw, SphereLinesLieAtItsRadius) {
    Scene s;
    const Vector centre(-2, 3, 1);
    s.world->sphere(centre, 0.7f, 1.0f);
    Recorder drawn = s.drawSpace(DEBUGDRAW_Shapes);
    ASSERT_EQ(drawn.lines.size(), size_t(3 * iDebugDraw::kCircleSegments));
    for (const Recorder::Line& l : drawn.lines) {
        EXPECT_NEAR(distance(l.from, centre), 0.7f, 1e-5f);
        EXPECT_NEAR(distance(l.to, centre), 0.7f, 1e-5f);
    }
}

TEST(DebugDraw, PlaneIsAGridPatchInThePlaneUnderTheScene) {
    Scene s;
    s.world->ground(-1.0f);
    s.world->box(Vector(20, 3, -4), Vector(1, 1, 1), 1.0f);
    Recorder drawn = s.drawSpace(DEBUGDRAW_Shapes);
    std::vector<Recorder::Line> grid = drawn.linesOf(debugcolour::kFixed);
    ASSERT_EQ(grid.size(), 23u); // 11 lines each way, and the normal
    float minX = 1e9f, maxX = -1e9f, minZ = 1e9f, maxZ = -1e9f;
    for (size_t i = 0; i + 1 < grid.size(); ++i) {
        for (const Vector& p : {grid[i].from, grid[i].to}) {
            EXPECT_FLOAT_EQ(p.y, -1.0f);
            minX = std::fmin(minX, p.x), maxX = std::fmax(maxX, p.x);
            minZ = std::fmin(minZ, p.z), maxZ = std::fmax(maxZ, p.z);
        }
    }
    // Under the box (the only other thing in the scene), and the normal goes up from the plane.
    EXPECT_LT(minX, 19.0f);
    EXPECT_GT(maxX, 21.0f);
    EXPECT_LT(minZ, -5.0f);
    EXPECT_GT(maxZ, -3.0f);
    EXPECT_FLOAT_EQ(grid.back().from.y, -1.0f);
    EXPECT_GT(grid.back().to.y, -1.0f);
    EXPECT_FLOAT_EQ(grid.back().to.x, grid.back().from.x);
}

TEST(DebugDraw, RestingSpheresContactNormalPointsUpAtTheTouchingPoint) {
    Scene s;
    settingsOf(s.scene)->setSleepingEnabled(false); // a sleeping pair with the ground has no contact
    s.world->ground(0.0f);
    iPhysicsFrame* ball = s.world->sphere(Vector(1, 0.5f, 2), 0.5f, 1.0f);
    s.run(60);
    const Vector c = ball->getDynamics()->position;
    Recorder drawn = s.drawSpace(DEBUGDRAW_ContactPoints | DEBUGDRAW_ContactNormals);
    std::vector<Recorder::Line> normals = drawn.linesOf(debugcolour::kContact);
    ASSERT_EQ(normals.size(), 1u);
    ASSERT_EQ(drawn.points.size(), 1u);
    const Vector touch = normals[0].from;
    EXPECT_NEAR(touch.x, c.x, 1e-3f);
    EXPECT_NEAR(touch.z, c.z, 1e-3f);
    EXPECT_NEAR(touch.y, 0.0f, 5e-3f); // the ground's surface, within the resting overlap
    EXPECT_EQ(drawn.points[0].at, touch);
    const Vector up = normals[0].to - normals[0].from;
    EXPECT_NEAR(up.x, 0.0f, 1e-5f);
    EXPECT_NEAR(up.z, 0.0f, 1e-5f);
    EXPECT_GT(up.y, 0.0f);
}

TEST(DebugDraw, SleepingBodiesAreMarkedOnceTheSceneSleeps) {
    Scene s;
    s.world->ground(0.0f);
    iPhysicsFrame* box = s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    s.run(6);
    ASSERT_EQ(statsOf(s.scene)->getAwakeBodyCount(), 1u);
    Recorder awake = s.draw(DEBUGDRAW_Shapes | DEBUGDRAW_Sleeping);
    EXPECT_TRUE(awake.texts.empty());
    EXPECT_EQ(awake.linesOf(debugcolour::kShape).size(), 12u);

    s.run(120);
    ASSERT_EQ(statsOf(s.scene)->getAwakeBodyCount(), 0u);
    Recorder asleep = s.draw(DEBUGDRAW_Shapes | DEBUGDRAW_Sleeping);
    ASSERT_EQ(asleep.texts.size(), 1u);
    EXPECT_EQ(asleep.texts[0].at, box->getDynamics()->position);
    EXPECT_EQ(asleep.texts[0].colour, debugcolour::kSleeping);
    EXPECT_EQ(asleep.linesOf(debugcolour::kSleeping).size(), 12u);
    EXPECT_EQ(asleep.linesOf(debugcolour::kShape).size(), 0u);

    Recorder unmarked = s.draw(DEBUGDRAW_Shapes); // the same sleeping box, sleeping not asked for
    EXPECT_TRUE(unmarked.texts.empty());
    EXPECT_EQ(unmarked.linesOf(debugcolour::kShape).size(), 12u);
}

TEST(DebugDraw, BodyAxesAreTheRotationsRowsFromTheCentreOfMass) {
    Scene s;
    const Matrix r = rotate(Vector(0, 1, 1), 0.4f);
    s.world->box(Vector(3, 4, 5), Vector(1, 1, 1), 1.0f, r);
    Recorder drawn = s.draw(DEBUGDRAW_BodyAxes);
    const DebugColour colours[3] = {debugcolour::kAxisX, debugcolour::kAxisY, debugcolour::kAxisZ};
    for (int row = 0; row < 3; ++row) {
        std::vector<Recorder::Line> axis = drawn.linesOf(colours[row]);
        ASSERT_EQ(axis.size(), 1u);
        EXPECT_EQ(axis[0].from, Vector(3, 4, 5));
        const Vector along = (axis[0].to - axis[0].from).normalize();
        EXPECT_NEAR(along.x, r(row, 0), 1e-5f);
        EXPECT_NEAR(along.y, r(row, 1), 1e-5f);
        EXPECT_NEAR(along.z, r(row, 2), 1e-5f);
    }
    ASSERT_EQ(drawn.points.size(), 1u);
    EXPECT_EQ(drawn.points[0].at, Vector(3, 4, 5));
}

// Which flag drew something, told by its kind and colour.
unsigned partOf(const Recorder::Line& l) {
    switch (l.colour) {
    case debugcolour::kShape:
    case debugcolour::kFixed:
    case debugcolour::kSleeping:
        return DEBUGDRAW_Shapes;
    case debugcolour::kBounds:
        return DEBUGDRAW_Bounds;
    case debugcolour::kContact:
        return DEBUGDRAW_ContactNormals;
    case debugcolour::kIsland:
        return DEBUGDRAW_Islands;
    default:
        return DEBUGDRAW_BodyAxes;
    }
}
std::map<unsigned, size_t> partsOf(const Recorder& r) {
    std::map<unsigned, size_t> parts;
    for (const Recorder::Line& l : r.lines) ++parts[partOf(l)];
    for (const Recorder::Mark& p : r.points)
        ++parts[p.colour == debugcolour::kContact ? DEBUGDRAW_ContactPoints : DEBUGDRAW_BodyAxes];
    parts[DEBUGDRAW_Sleeping] += r.texts.size();
    for (auto it = parts.begin(); it != parts.end();) it = it->second ? std::next(it) : parts.erase(it);
    return parts;
}

TEST(DebugDraw, EachFlagSwitchesItsPartAlone) {
    Scene s;
    settingsOf(s.scene)->setSleepingEnabled(false);
    s.world->ground(0.0f);
    s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f); // a stack of two: one island
    s.world->box(Vector(0, 1.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f);
    iPhysicsFrame* aloft = s.world->sphere(Vector(5, 5, 0), 0.5f, 1.0f);
    s.run(20);
    aloft->getDynamics()->sleeping = true; // read as drawn, no step taken: a sleeping body to mark

    const std::map<unsigned, size_t> all = partsOf(s.draw(DEBUGDRAW_All));
    EXPECT_TRUE(partsOf(s.draw(0)).empty());
    for (unsigned flag = 1; flag < DEBUGDRAW_All; flag <<= 1) {
        SCOPED_TRACE(flag);
        ASSERT_GT(all.count(flag), 0u); // every part has something to draw here
        // Alone, a flag draws its part and nothing else, as much of it as with every flag on.
        EXPECT_EQ(partsOf(s.draw(flag)), (std::map<unsigned, size_t>{{flag, all.at(flag)}}));
        std::map<unsigned, size_t> without = partsOf(s.draw(DEBUGDRAW_All & ~flag)), expected = all;
        expected.erase(flag);
        EXPECT_EQ(without, expected);
    }
}

TEST(DebugDraw, OctreeSpaceDrawsWhatTheSimpleSpaceDraws) {
    // One scene at a time: new bodies join the newest scene, new geometry the newest world's space.
    auto drawnWith = [](iCollisionSpace* space) {
        Scene s(space);
        settingsOf(s.scene)->setSleepingEnabled(false);
        s.world->ground(0.0f);
        s.world->box(Vector(0, 0.5f, 0), Vector(0.5f, 0.5f, 0.5f), 1.0f, rotatey(0.3f));
        s.world->sphere(Vector(0.2f, 1.6f, 0), 0.5f, 1.0f);
        s.run(30);
        return s.draw(DEBUGDRAW_All);
    };
    Recorder a = drawnWith(nullptr), b = drawnWith(CreateOctreeCollisionSpace());
    ASSERT_GT(a.lines.size(), 23u + 12u + 72u); // the ground, the box, the ball, and more
    ASSERT_EQ(a.lines.size(), b.lines.size());
    for (size_t i = 0; i < a.lines.size(); ++i) {
        EXPECT_EQ(a.lines[i].from, b.lines[i].from);
        EXPECT_EQ(a.lines[i].to, b.lines[i].to);
        EXPECT_EQ(a.lines[i].colour, b.lines[i].colour);
    }
    EXPECT_EQ(a.points.size(), b.points.size());
}

} // namespace debugdraw_test
