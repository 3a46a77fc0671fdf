// GameDesign.cpp - scene building, hit counting, the per-second summary and the blow-up checks.
#include "GameDesign.h"

#include "SvgDebugDraw.h"
#include "World.h"
#include "iCollisionListener.h"
#include "iCollisionSpace.h"
#include "iDebugDrawable.h"
#include "iPhysicsFrame.h"
#include "iPhysicsScene.h"
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

GameDesign::GameDesign(iPhysicsScene* scene, const SceneSpec& spec, int frames)
    : m_scene(scene), m_spec(spec), m_frames(frames) {}

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
    std::printf("scene %s: %s; %zu bodies\n", m_spec.name, m_spec.description, m_world->bodies().size());
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
    if (second != m_lastSecond || finished()) {
        m_lastSecond = second;
        summarise(now);
    }
    if (!m_imageDir.empty() && (m_frame % m_imageEvery == 0 || finished())) writeImage();
    if (m_failure) std::printf("BLEW UP at %.3f s: %s\n", (now - m_start) / 1000.0, m_failure);
}

void GameDesign::summarise(int now) {
    auto wall = std::chrono::steady_clock::now();
    double ms = std::chrono::duration<double, std::milli>(wall - m_wallStart).count();
    double perFrame = m_framesThisSecond ? ms / m_framesThisSecond : 0.0;
    m_wallStart = wall;
    m_framesThisSecond = 0;
    // Everything but the last column is deterministic (a stepped clock drives the run).
    std::printf("t %6.2f s  bodies %4zu  awake %4zu  contacts %5zu  KE %10.4f J  max pen %.4f m  hits %6ld"
                "  | %.3f ms/frame\n",
                (now - m_start) / 1000.0, statsOf(m_scene)->getBodyCount(),
                statsOf(m_scene)->getAwakeBodyCount(), m_world->space()->getNumContacts(),
                m_world->kineticEnergy(), m_worstPenetration, m_hits->hits, perFrame);
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
