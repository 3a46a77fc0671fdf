// FuzzObjects.cpp - the fuzz walk's creation, attachment and deletion of scenes, bodies, frames, spaces
// and geometries (World.h).
#include "World.h"

namespace fuzz {

void World::newScene() {
    iPhysicsScene* s = CreatePhysicsScene(nullptr);
    m_scenes.push_back(s);
    settingsOf(s)->setMaxStepsPerUpdate(1 + pick(6));
    if (pick(2) && !m_spaces.empty()) s->setNewGlobalCollisionSpace(any(m_spaces));
}

void World::deleteScene() {
    iPhysicsScene* s = any(m_scenes);
    if (!s) return;
    m_stats.steps += (unsigned long)statsOf(s)->getStepCount();
    erase(m_scenes, s);
    s->Delete(); // its bodies are reported dead (bodyDied) when they go, maybe at the end of a step
}

void World::newBody() {
    iRigidBody* b = CreateRigidBody(pick(3) == 0 ? anyFrame() : nullptr);
    m_bodies.push_back(b);
    if (pick(2)) b->getDynamics().position = Vector(unit(), unit(), unit()) * 5.0f;
}

void World::deleteBody() {
    if (pick(4) == 0 && !m_pframes.empty()) { // refused: a PhysicsFrame owns it
        any(m_pframes)->getRB()->Delete();
        return;
    }
    iRigidBody* b = any(m_bodies);
    if (!b) return;
    erase(m_bodies, b);
    b->Delete();
}

void World::framesAndPhysicsFrames() {
    if (pick(2)) {
        Frame* f = static_cast<Frame*>(CreateFrame());
        f->translate(unit() * 5, unit() * 5, unit() * 5);
        if (iFrame* p = anyFrame(); p && pick(2)) f->attachTo(p);
        m_frames.push_back(f);
    } else {
        iPhysicsFrame* pf = CreatePhysicsFrame();
        pf->translate(unit() * 5, unit() * 5, unit() * 5);
        m_pframes.push_back(pf);
    }
}

void World::deleteFrame() {
    if (pick(2) && !m_pframes.empty()) { // deletion in any order: children, bound bodies and all
        deletePhysicsFrame(any(m_pframes));
        return;
    }
    iFrame* f = any(m_frames);
    if (!f) return;
    // The documented rule for a framework Frame: whoever points at it lets go first.
    for (iRigidBody* b : m_bodies)
        if (b->getFrame() == f) b->attach(nullptr);
    for (iPhysicsFrame* pf : m_pframes) {
        if (pf->getRB()->getFrame() == f) pf->getRB()->attach(nullptr);
        if (pf->parent() == f) pf->attachTo(nullptr);
    }
    for (iFrame* g : m_frames)
        if (g->parent() == f) g->attachTo(nullptr);
    erase(m_frames, f);
    f->Delete();
}

void World::deletePhysicsFrame(iPhysicsFrame* pf) {
    if (!pf) return;
    for (iFrame* g : m_frames)
        if (g->parent() == pf) g->attachTo(nullptr);
    erase(m_pframes, pf);
    pf->Delete();
}

void World::attachments() {
    switch (pick(5)) {
    case 0:
        if (iRigidBody* b = anyBody()) b->attach(pick(3) ? anyFrame() : nullptr);
        break;
    case 1: // the bodies' own chains
        if (iRigidBody* b = anyBody()) {
            iRigidBody* p = pick(4) ? anyBody() : nullptr;
            b->getDynamics().attachTo(p ? &p->getDynamics() : nullptr);
        }
        break;
    case 2:
        if (iPhysicsFrame* pf = any(m_pframes)) pf->attachTo(pick(4) ? anyFrame() : nullptr);
        break;
    case 3:
        if (iFrame* f = any(m_frames)) f->attachTo(pick(3) ? anyFrame() : nullptr);
        break;
    default:
        if (iFrame* f = anyFrame()) {
            f->translate(value(), unit(), unit());
            f->rotatey(unit());
        }
        break;
    }
}

void World::spaces() {
    switch (pick(4)) {
    case 0:
        if (m_spaces.size() < 3) m_spaces.push_back(CreateSimpleCollisionSpace(size_t(pick(3) * 60)));
        break;
    case 1: // deleted in any order: before the scenes colliding in it, before its geometries
        deleteSpace(any(m_spaces));
        break;
    case 2:
        if (iPhysicsScene* s = any(m_scenes))
            s->setNewGlobalCollisionSpace(pick(4) ? any(m_spaces) : nullptr);
        break;
    default:
        if (iCollisionSpace* cs = any(m_spaces)) {
            if (iCollisionGeometry* g = any(m_geoms)) {
                if (pick(2))
                    cs->add(g);
                else
                    cs->remove(g);
            }
        }
        break;
    }
}

void World::deleteSpace(iCollisionSpace* cs) {
    if (!cs) return;
    const unsigned long before = errorCount();
    cs->Delete();
    if (errorCount() == before) erase(m_spaces, cs);
}

void World::newGeometry() {
    iRigidBody* b = pick(5) ? anyBody() : nullptr;
    iCollisionGeometry* g = nullptr;
    switch (pick(4)) {
    case 0:
        g = CreateCSphere(b, pick(6) ? 0.2f + std::fabs(unit()) : value());
        break;
    case 1:
        g = CreateCOBB(b, pick(6) ? Vector(0.5f, 0.3f, 0.4f) : vec());
        break;
    case 2:
        g = CreateCPlane(b, pick(5) ? Vector(0, 1, 0) : vec(), unit() * 3);
        break;
    default: {
        g = CreateCCompound(b);
        auto* c = static_cast<iCCompound*>(g);
        for (int i = pick(3); i > 0; --i) {
            if (pick(2))
                c->addSphere(vec(), 0.3f + std::fabs(unit()));
            else
                c->addBox(vec(), rotation(), Vector(0.2f, 0.3f, 0.4f));
        }
        break;
    }
    }
    if (g) m_geoms.push_back(g); // nullptr: a refused size
}

void World::deleteGeometry() {
    iCollisionGeometry* g = any(m_geoms);
    if (!g) return;
    erase(m_geoms, g);
    g->Delete();
}

void World::clones() {
    if (pick(2)) {
        if (iRigidBody* b = anyBody()) m_bodies.push_back(b->clone());
    } else if (iPhysicsFrame* pf = any(m_pframes)) {
        m_pframes.push_back(pf->clone());
    } else if (iCollisionGeometry* g = any(m_geoms)) {
        if (iCollisionGeometry* c = g->clone()) m_geoms.push_back(c);
    }
}

} // namespace fuzz
