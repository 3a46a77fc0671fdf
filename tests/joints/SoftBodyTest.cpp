// SoftBodyTest.cpp - soft bodies (iSoftBody) through whole scenes: the springs of irregular masks against a
// brute-force count over all pairs of places, the bodies where the mask says, tightness and damping for
// every spring, free fall by momentum conservation, the two-body period 2 pi sqrt(mu / k), killAll, and
// refused input.
#include "JointTestSupport.h"
#include "iLifetime.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"
#include "iSoftBody.h"
#include "iSpring.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>
#include <vector>

using namespace joint_test;

namespace {

// A grid place, (column, row).
using Place = std::pair<int, int>;
using PlacePair = std::pair<Place, Place>; // first < second

struct Mask {
    int columns, rows;
    std::vector<char> holds; // row by row ('X' holds a body)
    bool at(int c, int r) const { return holds[size_t(r * columns + c)] == 'X'; }
    std::vector<bool> asBools() const {
        std::vector<bool> out;
        for (char h : holds) out.push_back(h == 'X');
        return out;
    }
};

Mask maskFrom(int columns, const char* rowsText) {
    Mask m{columns, 0, {}};
    for (const char* p = rowsText; *p; ++p) m.holds.push_back(*p);
    m.rows = int(m.holds.size()) / columns;
    return m;
}

// Every pair of places holding bodies whose offset (|dc|, |dr|) is a neighbour's: structural (1,0) (0,1),
// shear (1,1), bend (2,0) (0,2). All pairs are tried, not the six directions the factory walks.
std::set<PlacePair> bruteForceSpringPairs(const Mask& m) {
    std::vector<Place> places;
    for (int r = 0; r < m.rows; ++r)
        for (int c = 0; c < m.columns; ++c)
            if (m.at(c, r)) places.push_back({c, r});
    const std::set<Place> neighbour{{1, 0}, {0, 1}, {1, 1}, {2, 0}, {0, 2}};
    std::set<PlacePair> pairs;
    for (size_t i = 0; i < places.size(); ++i)
        for (size_t j = i + 1; j < places.size(); ++j) {
            const Place offset{std::abs(places[i].first - places[j].first),
                               std::abs(places[i].second - places[j].second)};
            if (neighbour.count(offset))
                pairs.insert({std::min(places[i], places[j]), std::max(places[i], places[j])});
        }
    return pairs;
}

iSoftBody* makeSoftBody(const Mask& m, const Vector& corner, const Vector& columnStep, const Vector& rowStep,
                        float mass, float k, float c) {
    const std::vector<bool> bools = m.asBools();
    bool* mask = new bool[bools.size()];
    for (size_t i = 0; i < bools.size(); ++i) mask[i] = bools[i];
    iSoftBody* body = CreateSoftBody(mask, m.columns, m.rows, corner, columnStep, rowStep, mass, k, c);
    delete[] mask;
    return body;
}

Vector momentumOf(const iSoftBody* s) {
    Vector p;
    for (int i = 0; i < s->getBodyCount(); ++i) {
        const RBDynamics& d = s->getBody(i)->getDynamics();
        p += d.velocity * d.mass;
    }
    return p;
}

Vector centreOfMassOf(const iSoftBody* s) {
    Vector sum;
    float mass = 0;
    for (int i = 0; i < s->getBodyCount(); ++i) {
        const RBDynamics& d = s->getBody(i)->getDynamics();
        sum += d.position * d.mass;
        mass += d.mass;
    }
    return sum / mass;
}

} // namespace

// An L shape and a ring with a hole, on skewed steps: the bodies sit exactly where the mask holds one (at
// corner + c columnStep + r rowStep, row by row), and the springs join exactly the brute-force pairs, each
// at rest at its pair's distance.
TEST(SoftBody, SpringsJoinExactlyTheNeighbourPairsOfAnIrregularMask) {
    StepScene s;
    const Mask lShape = maskFrom(4, "X..."
                                    "X..."
                                    "X..."
                                    "XXXX"
                                    "XXXX");
    const Mask ring = maskFrom(5, "XXXX."
                                  "XXXXX"
                                  "XX.XX"
                                  "XXXXX"
                                  "XXXXX");
    const Vector corner(1, 2, -1), columnStep(0.3f, 0, 0), rowStep(0.05f, 0, 0.4f);
    for (const Mask& m : {lShape, ring}) {
        iSoftBody* soft = makeSoftBody(m, corner, columnStep, rowStep, 0.5f, 100.0f, 0.5f);
        ASSERT_NE(soft, nullptr);
        EXPECT_EQ(soft->getColumns(), m.columns);
        EXPECT_EQ(soft->getRows(), m.rows);
        std::map<const iRigidBody*, Place> placeOf;
        int index = 0;
        for (int r = 0; r < m.rows; ++r)
            for (int c = 0; c < m.columns; ++c) {
                iRigidBody* b = soft->getBodyAt(c, r);
                EXPECT_EQ(b != nullptr, m.at(c, r)) << c << ", " << r;
                if (!b) continue;
                EXPECT_EQ(soft->getBody(index++), b); // row by row
                const Vector expected = corner + columnStep * float(c) + rowStep * float(r);
                EXPECT_LT((b->getDynamics().position - expected).length(), 1e-6f);
                placeOf[b] = {c, r};
            }
        EXPECT_EQ(soft->getBodyCount(), index);
        EXPECT_EQ(soft->getBody(index), nullptr);
        EXPECT_EQ(soft->getBodyAt(-1, 0), nullptr);
        EXPECT_EQ(soft->getBodyAt(m.columns, 0), nullptr);
        EXPECT_EQ(soft->getBodyAt(0, m.rows), nullptr);

        const std::set<PlacePair> expected = bruteForceSpringPairs(m);
        std::set<PlacePair> made;
        for (int i = 0; i < soft->getSpringCount(); ++i) {
            const iSpring* spring = soft->getSpring(i);
            const Place a = placeOf.at(spring->getBodyA()), b = placeOf.at(spring->getBodyB());
            made.insert({std::min(a, b), std::max(a, b)});
            const Vector apart = columnStep * float(b.first - a.first) + rowStep * float(b.second - a.second);
            EXPECT_NEAR(spring->getRestLength(), apart.length(), 1e-6f);
        }
        EXPECT_EQ(soft->getSpringCount(), int(expected.size())); // no pair twice
        EXPECT_EQ(made, expected);
        EXPECT_EQ(soft->getSpring(soft->getSpringCount()), nullptr);
        std::printf("[ measured ] %dx%d mask: %d bodies, %d springs (brute force %zu)\n", m.columns, m.rows,
                    soft->getBodyCount(), soft->getSpringCount(), expected.size());
        soft->Delete();
    }
    EXPECT_EQ(statsOf(s.scene())->getBodyCount(), 0u); // never in the scene
}

// setTightness and setDamping reach every spring; refused values (negative, NaN, infinite) change none.
TEST(SoftBody, TightnessAndDampingApplyToEverySpring) {
    const Mask full = maskFrom(3, "XXXXXXXXX");
    iSoftBody* soft = makeSoftBody(full, Vector(), Vector(1, 0, 0), Vector(0, 1, 0), 1.0f, 10.0f, 0.0f);
    ASSERT_NE(soft, nullptr);
    ASSERT_EQ(soft->getSpringCount(), 26); // by hand: 12 structural, 8 shear, 6 bend
    EXPECT_TRUE(soft->setTightness(123.5f));
    EXPECT_TRUE(soft->setDamping(0.75f));
    {
        ErrorRecorder errors;
        EXPECT_FALSE(soft->setTightness(-1.0f));
        EXPECT_FALSE(soft->setTightness(std::nanf("")));
        EXPECT_FALSE(soft->setTightness(INFINITY));
        EXPECT_FALSE(soft->setDamping(-0.1f));
        EXPECT_FALSE(soft->setDamping(std::nanf("")));
        EXPECT_EQ(errors.count(), 5u);
    }
    for (int i = 0; i < soft->getSpringCount(); ++i) {
        EXPECT_EQ(soft->getSpring(i)->getStiffness(), 123.5f) << i;
        EXPECT_EQ(soft->getSpring(i)->getDamping(), 0.75f) << i;
    }
    soft->Delete();
}

// A 3x3 sheet of 0.5 kg bodies thrown with one corner pulled out and one body moving (the springs busy):
// the springs' forces cancel, so after 1 s the momentum is P0 + M g t and the centre of mass is where a lone
// particle would be: in the joint solver's sub-steps h = 1 / (60 iterations) semi-implicit Euler takes it
// exactly to c0 + (P0 / M) t + g (t^2 + t h) / 2 (the parabola g t^2 / 2 plus g t h / 2 = 2 cm).
TEST(SoftBody, AFreeFallingSoftBodyKeepsMomentumPlusMgt) {
    StepScene s(60);
    const Mask full = maskFrom(3, "XXXXXXXXX");
    iSoftBody* soft =
        makeSoftBody(full, Vector(0, 5, 0), Vector(0.5f, 0, 0), Vector(0, 0, 0.5f), 0.5f, 200.0f, 1.0f);
    ASSERT_NE(soft, nullptr);
    soft->getBodyAt(2, 2)->getDynamics().position += Vector(0.1f, 0.05f, 0);
    soft->getBodyAt(0, 0)->getDynamics().velocity = Vector(0.3f, 0, -0.2f);
    const float M = 9 * 0.5f, t = 1;
    const Vector p0 = momentumOf(soft), c0 = centreOfMassOf(soft), g(0, -kG, 0);
    ASSERT_TRUE(soft->addToScene(s.scene()));
    s.seconds(t);
    const Vector momentumMiss = momentumOf(soft) - (p0 + g * (M * t));
    const float h = 1.0f / float(60 * settingsOf(s.scene())->getSolverIterations());
    const Vector comMiss = centreOfMassOf(soft) - (c0 + p0 * (t / M) + g * ((t * t + t * h) / 2));
    EXPECT_LT(momentumMiss.length(), 2e-4f); // of M g t = 44 kg m/s
    EXPECT_LT(comMiss.length(), 1e-4f);
    const float spread =
        (soft->getBodyAt(2, 2)->getDynamics().position - soft->getBodyAt(0, 0)->getDynamics().position)
            .length();
    EXPECT_GT(std::fabs(spread - std::sqrt(2.0f)), 1e-3f); // the springs were still moving it
    std::printf("[ measured ] free fall: momentum off by %.2e kg m/s, centre of mass by %.2e m\n",
                momentumMiss.length(), comMiss.length());
    soft->Delete();
}

// Two 1 kg bodies 1 m apart on one spring (k = 50 N/m), weightless, let go stretched by 0.1 m: they
// oscillate with the reduced mass mu = m / 2, period 2 pi sqrt(mu / k) = 0.628 s (omega dt = 0.17 at 60 Hz)
// within 1 %, and their centre of mass stays put.
TEST(SoftBody, TwoBodiesOscillateWithTheReducedMassPeriod) {
    StepScene s(60);
    settingsOf(s.scene())->setGravity(Vector(0, 0, 0));
    const float m = 1, k = 50;
    const Mask pair = maskFrom(2, "XX");
    iSoftBody* soft = makeSoftBody(pair, Vector(0, 0, 0), Vector(1, 0, 0), Vector(0, 1, 0), m, k, 0.0f);
    ASSERT_NE(soft, nullptr);
    ASSERT_EQ(soft->getSpringCount(), 1);
    iRigidBody *left = soft->getBodyAt(0, 0), *right = soft->getBodyAt(1, 0);
    right->getDynamics().position = Vector(1.1f, 0, 0);
    const Vector c0 = centreOfMassOf(soft);
    ASSERT_TRUE(soft->addToScene(s.scene()));
    std::vector<double> stretch;
    s.recorder.fn = [&] {
        stretch.push_back(right->getDynamics().position.x - left->getDynamics().position.x - 1.0);
    };
    s.seconds(5);
    const double period = meanPeriod(stretch, 1.0 / 60), truth = 2 * M_PI * std::sqrt(m / 2 / k);
    EXPECT_NEAR(period / truth, 1.0, 0.01) << period;
    EXPECT_LT((centreOfMassOf(soft) - c0).length(), 1e-5f);
    std::printf("[ measured ] two-body spring: period %.5f s, analytic %.5f s (%.3f %%)\n", period, truth,
                (period / truth - 1) * 100);
    soft->Delete();
}

// killAll: after one step every body has left the scene (a bystander stays), isAlive() is false, and every
// spring let go.
TEST(SoftBody, KillAllTakesEveryBodyOutAndTheSpringsLetGo) {
    StepScene s(60);
    iRigidBody* bystander = sphereBody(Vector(5, 0, 0), 1.0f, 0.1f);
    const Mask ring = maskFrom(3, "XXXX.XXXX");
    iSoftBody* soft = makeSoftBody(ring, Vector(), Vector(1, 0, 0), Vector(0, 1, 0), 1.0f, 10.0f, 0.1f);
    ASSERT_NE(soft, nullptr);
    ASSERT_TRUE(soft->addToScene(s.scene()));
    s.step(5);
    EXPECT_EQ(statsOf(s.scene())->getBodyCount(), 9u);
    soft->killAll();
    s.step(1);
    EXPECT_EQ(statsOf(s.scene())->getBodyCount(), 1u);
    for (int i = 0; i < soft->getBodyCount(); ++i) EXPECT_FALSE(lifetimeOf(soft->getBody(i))->isAlive()) << i;
    for (int i = 0; i < soft->getSpringCount(); ++i) EXPECT_FALSE(soft->getSpring(i)->isActive()) << i;
    soft->Delete();
    bystander->Delete();
}

// A scene's Delete() deletes the bodies in it, the soft body's among them: it reads them as nullptr from
// then on (getBody and getBodyAt), and its Delete() deletes only its springs (no double delete).
TEST(SoftBody, ASceneDeletedFirstTakesTheBodiesAndTheSoftBodyForgetsThem) {
    iPhysicsScene* scene = CreatePhysicsScene(nullptr);
    const Mask square = maskFrom(2, "XXXX");
    iSoftBody* soft = makeSoftBody(square, Vector(), Vector(1, 0, 0), Vector(0, 1, 0), 1.0f, 10.0f, 0.0f);
    ASSERT_NE(soft, nullptr);
    ASSERT_TRUE(soft->addToScene(scene));
    physics_test::DestroyLog destroyed;
    scene->Delete();
    EXPECT_EQ(destroyed.dead.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(soft->getBody(i), nullptr) << i;
    for (int i = 0; i < 4; ++i) EXPECT_EQ(soft->getBodyAt(i % 2, i / 2), nullptr) << i;
    for (int i = 0; i < soft->getSpringCount(); ++i) EXPECT_FALSE(soft->getSpring(i)->isActive()) << i;
    soft->killAll(); // nothing left to kill: no effect
    soft->Delete();
    EXPECT_EQ(destroyed.dead.size(), 4u);
}

// Each bad input is refused with nullptr and one error(): no mask, a mask with no body, no columns or rows,
// a non-finite corner or step, a zero step, parallel steps, mass <= 0 or NaN, negative or infinite k, c.
TEST(SoftBody, BadInputIsRefusedWithAnError) {
    StepScene s;
    const bool mask[4] = {true, true, false, true}, none[4] = {false, false, false, false};
    const Vector o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), nan(std::nanf(""), 0, 0);
    ErrorRecorder errors;
    unsigned long refused = 0;
    auto refuses = [&](iSoftBody* made) {
        ++refused;
        EXPECT_EQ(made, nullptr) << "case " << refused;
        EXPECT_EQ(errors.count(), refused) << "case " << refused;
    };
    refuses(CreateSoftBody(nullptr, 2, 2, o, x, y, 1, 10, 0));
    refuses(CreateSoftBody(none, 2, 2, o, x, y, 1, 10, 0));
    refuses(CreateSoftBody(mask, 0, 2, o, x, y, 1, 10, 0));
    refuses(CreateSoftBody(mask, 2, -1, o, x, y, 1, 10, 0));
    refuses(CreateSoftBody(mask, 2, 2, nan, x, y, 1, 10, 0));
    refuses(CreateSoftBody(mask, 2, 2, o, nan, y, 1, 10, 0));
    refuses(CreateSoftBody(mask, 2, 2, o, Vector(), y, 1, 10, 0));
    refuses(CreateSoftBody(mask, 2, 2, o, x, x * 2, 1, 10, 0));
    refuses(CreateSoftBody(mask, 2, 2, o, x, y, 0, 10, 0));
    refuses(CreateSoftBody(mask, 2, 2, o, x, y, std::nanf(""), 10, 0));
    refuses(CreateSoftBody(mask, 2, 2, o, x, y, 1, -1, 0));
    refuses(CreateSoftBody(mask, 2, 2, o, x, y, 1, INFINITY, 0));
    refuses(CreateSoftBody(mask, 2, 2, o, x, y, 1, 10, -0.5f));
    EXPECT_EQ(statsOf(s.scene())->getBodyCount(), 0u);
    // the same input with every value sound is accepted (the cases above each break one thing)
    iSoftBody* sound = CreateSoftBody(mask, 2, 2, o, x, y, 1, 10, 0);
    ASSERT_NE(sound, nullptr);
    EXPECT_EQ(sound->getBodyCount(), 3);
    EXPECT_EQ(sound->getSpringCount(), 3); // two structural, one shear
    EXPECT_EQ(errors.count(), refused);
    sound->Delete();
}
