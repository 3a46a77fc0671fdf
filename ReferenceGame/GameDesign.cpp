// GameDesign.cpp - scene building, hit counting, the per-second summary, CSV rows and the blow-up checks.
#include "GameDesign.h"

#include "CsvLog.h"
#include "RBDynamics.h"
#include "RecordingWriter.h"
#include "SvgDebugDraw.h"
#include "World.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iDebugDrawable.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
#include "iPhysicsSceneProfile.h"
#include "iPhysicsSceneSettings.h"
#include "iPhysicsSceneStats.h"
#include "iRigidBody.h"

#include <cstdio>

struct HitCounter final : iCollisionListener {
    long hits = 0;
    void HitWall(iRigidBody*, Vector, Vector) override { ++hits; }
};

namespace {
// Blow-up bounds: energy may not grow past what the scene had (plus what shots put in) by more than 2% + 1 J,
// and no contact may be deeper than 0.25 m.
const float kEnergyTolerance = 0.02f, kEnergySlackJ = 1.0f, kMaxPenetration = 0.25f;
} // namespace

GameDesign::GameDesign(iPhysicsScene* scene, const SceneSpec& spec, const GameOptions& options, CsvLog* csv)
    : m_scene(scene), m_spec(spec), m_options(options), m_csv(csv), m_frames(options.frames),
      m_csvEvery(options.csvEvery) {}

GameDesign::~GameDesign() {
    delete m_world;
    delete m_hits;
}

void GameDesign::initialize(int now) {
    m_start = now;
    m_world = new World(m_scene);
    m_spec.build(*m_world);
    m_hits = new HitCounter();
    for (iPhysicsFrame* f : m_world->bodies()) f->getRB()->attachListener(m_hits);
    m_energyBudget = m_world->mechanicalEnergy();
    m_wallStart = std::chrono::steady_clock::now();
    std::fprintf(m_options.out, "scene %s: %s; %zu bodies\n", m_spec.name, m_spec.description,
                 m_world->bodies().size() + m_world->parts().size()); // a rope's or soft body's too
    m_tracker.resolve(*m_world, m_options.track, m_spec.name, m_options.err);
    if (m_recording) { // the scene as built: frame 0
        m_recording->begin(*m_world, m_spec.name);
        m_recording->frame(*m_world, 0, 0, statsOf(m_scene)->getStepCount(), 0.0f);
    }
    if (m_csv) {
        m_csv->header(m_tracker.names());
        m_csv->row(measure(now, 0), m_tracker.positions()); // the start, t = 0
    }
}

void GameDesign::update(int now) {
    ++m_frame;
    ++m_framesThisSecond;
    if (m_spec.act) {
        size_t before = m_world->bodies().size();
        float energyBefore = m_world->mechanicalEnergy();
        m_spec.act(*m_world, m_frame);
        for (size_t i = before; i < m_world->bodies().size(); ++i)
            m_world->bodies()[i]->getRB()->attachListener(m_hits);
        m_energyBudget += m_world->mechanicalEnergy() - energyBefore;
    }
    // The deepest overlap the solver left this step (a swept contact's depth at first touch is not an
    // overlap).
    float penetration = statsOf(m_scene)->getRemainingPenetration();
    if (penetration > m_worstPenetration) m_worstPenetration = penetration;
    if (!m_world->allFinite())
        m_failure = "a body's state is not finite";
    else if (m_world->mechanicalEnergy() > m_energyBudget * (1 + kEnergyTolerance) + kEnergySlackJ)
        m_failure = "energy grew";
    else if (penetration > kMaxPenetration)
        m_failure = "a contact is deeper than 0.25 m";
    int second = (now - m_start) / 1000;
    bool summary = second != m_lastSecond || finished();
    if (summary || (m_csv && m_csvEvery > 0 && m_frame % m_csvEvery == 0)) {
        const GameSample s = measure(now, penetration);
        if (m_csv && (m_csvEvery > 0 ? m_frame % m_csvEvery == 0 || finished() : summary))
            m_csv->row(s, m_tracker.positions());
        if (summary) {
            m_lastSecond = second;
            summarise(s);
        }
    }
    if (m_recording)
        m_recording->frame(*m_world, m_frame, now - m_start, statsOf(m_scene)->getStepCount(), penetration);
    if (!m_imageDir.empty() && (m_frame % m_imageEvery == 0 || finished())) writeImage();
    if (m_failure)
        std::fprintf(m_options.out, "BLEW UP at %.3f s: %s\n", (now - m_start) / 1000.0, m_failure);
}

GameSample GameDesign::measure(int now, float penetration) const {
    GameSample s;
    s.time = (now - m_start) / 1000.0;
    const iPhysicsSceneStats* stats = statsOf(m_scene);
    s.simTime = double(stats->getStepCount()) / settingsOf(m_scene)->getStepRate();
    s.frame = m_frame;
    s.kinetic = m_world->kineticEnergy();
    s.mechanical = m_world->mechanicalEnergy();
    s.awake = stats->getAwakeBodyCount();
    s.bodies = stats->getBodyCount();
    for (const iPhysicsFrame* f : m_world->bodies())
        s.moving += f->getDynamics()->physicsType != PHYS_FixedInSpace;
    for (const World::Part& p : m_world->parts())
        s.moving += p.body->getDynamics().physicsType != PHYS_FixedInSpace;
    s.contacts = m_world->space()->getNumContacts();
    s.overlap = penetration;
    s.worstOverlap = m_worstPenetration;
    s.hits = m_hits->hits;
    return s;
}

void GameDesign::summarise(const GameSample& s) {
    auto wall = std::chrono::steady_clock::now();
    double ms = std::chrono::duration<double, std::milli>(wall - m_wallStart).count();
    double perFrame = m_framesThisSecond ? ms / m_framesThisSecond : 0.0;
    m_wallStart = wall;
    m_framesThisSecond = 0;
    printSummaryLine(m_options.out, s, perFrame);
    m_tracker.print(m_options.out);
    if (m_options.profile) printProfile();
}

void printSummaryLine(std::FILE* out, const GameSample& s, double msPerFrame) {
    // Everything but the last column is deterministic (a stepped clock drives the run). "asleep": every
    // moving body sleeps, so no contact is tested (contacts 0) and nothing moves.
    std::fprintf(out,
                 "t %6.2f s  awake %4zu/%-4zu%s  contacts %5zu  KE %10.4f J  max pen %.4f m  hits %6ld"
                 "  | %.3f ms/frame\n",
                 s.time, s.awake, s.moving, s.allAsleep() ? " asleep" : "       ", s.contacts, s.kinetic,
                 s.worstOverlap, s.hits, msPerFrame);
}

// Where the last update's step time went (its steps' sum), phase by phase, and what it worked on.
void GameDesign::printProfile() const {
    const iPhysicsSceneProfile* profile = profileOf(m_scene);
    if (!profile) return;
    const PhysicsProfile& p = profile->getProfile();
    auto ms = [](double s) { return s * 1000.0; };
    std::fprintf(m_options.out,
                 "profile %d steps %.3f ms: updaters %.3f edits %.3f collision %.3f islands %.3f integration "
                 "%.3f solver %.3f continuous %.3f sleeping %.3f events %.3f | bodies %zu awake %zu contacts "
                 "%zu pairs %zu rows %zu\n",
                 p.steps, ms(p.total), ms(p.updaters), ms(p.edits), ms(p.collision), ms(p.islands),
                 ms(p.integration), ms(p.solver), ms(p.continuous), ms(p.sleeping), ms(p.events), p.bodies,
                 p.awakeBodies, p.contacts, p.touchingPairs, p.solverRows);
}

void GameDesign::writeImage() {
    SvgDebugDraw picture;
    if (const iDebugDrawable* drawable = debugDrawOf(m_scene))
        drawable->debugDraw(picture, DEBUGDRAW_Default);
    char name[64];
    std::snprintf(name, sizeof name, "_%05d.svg", m_frame);
    const std::string path = m_imageDir + "/" + m_spec.name + name;
    if (!picture.write(path)) {
        std::fprintf(stderr, "cannot write %s\n", path.c_str());
        if (!m_failure) m_failure = "cannot write an image";
    }
}
