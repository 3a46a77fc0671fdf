// Rope.cpp - a rope (iRope.h, seed 000's Rope): segment bodies evenly spaced from start to end, each joined
// to the next by a distance joint with limits (0, spacing) that goes slack but does not stretch, and an
// optional ball-joint pin at either end.
//
// Segments: point-like, mass segmentMass, the inertia of a solid sphere of radius a quarter of the spacing
// (small against the link, so a segment turns freely and its spin hardly stores energy). They are made as
// physics::RigidBody directly, not with CreateRigidBody, which would add them to the active scene: the
// rope's bodies are in no scene until addToScene. They have no collision geometry (Physics/ never sees
// Collision/): the game gives them shapes.
//
// The segments are a BodyGroup: a segment deleted by anyone else (its scene's Delete()) reads nullptr from
// then on, and the rope's own Delete() skips it instead of deleting it twice.
#include "BodyGroup.h"

#include "iBallJoint.h"
#include "iDistanceJoint.h"
#include "iPhysicsScene.h"
#include "iRope.h"
#include "iUtilities.h"

#include <cmath>
#include <vector>

namespace physics {

namespace {

class Rope final : public iRope {
public:
    Rope(const Vector& start, const Vector& end, int segments, float segmentMass) {
        const float spacing = (end - start).length() / float(segments - 1);
        for (int i = 0; i < segments; ++i) {
            const float along = float(i) / float(segments - 1);
            m_group.makeBody(start + (end - start) * along, segmentMass, spacing / 4);
        }
        m_links.reserve(size_t(segments - 1));
        for (int i = 0; i + 1 < segments; ++i) {
            iRigidBody *a = m_segments[size_t(i)], *b = m_segments[size_t(i) + 1];
            iDistanceJoint* link =
                CreateDistanceJoint(a, b, a->getDynamics().position, b->getDynamics().position);
            if (!link) return; // cannot happen with the checked input; complete() tells the factory
            // Slack down to zero, never longer than at creation: a rope, not a rod.
            link->setLimits(0.0f, link->getMaxLength());
            m_links.push_back(link);
        }
    }
    bool complete() const { return m_links.size() + 1 == m_segments.size(); }

    int getSegmentCount() const override { return int(m_segments.size()); }
    iRigidBody* const* getSegments() const override { return m_segments.data(); }
    iDistanceJoint* getLink(int i) const override {
        return i >= 0 && size_t(i) < m_links.size() ? m_links[size_t(i)] : nullptr;
    }

    bool pin(bool atStart, iRigidBody* body) override {
        for (iRigidBody* segment : m_segments)
            if (body && segment == body) { // (a deleted segment reads nullptr, the world's pin)
                error(L"iRope::pin: the body is one of the rope's own segments; refused");
                return false;
            }
        iRigidBody* end = atStart ? m_segments.front() : m_segments.back();
        if (!end) {
            error(L"iRope::pin: that end's segment was deleted; refused");
            return false;
        }
        iBallJoint* pin = CreateBallJoint(end, body, end->getDynamics().position);
        if (!pin) return false; // the factory said why
        iBallJoint*& slot = m_pins[atStart ? 0 : 1];
        if (slot) slot->Delete(); // replaced only once the new pin exists
        slot = pin;
        return true;
    }

    bool addToScene(iPhysicsScene* scene) override { return m_group.addTo(scene, L"iRope"); }
    void killAll() override { m_group.killAll(); }

    // The joints first (they let go of nothing then), then the bodies; each Delete() waits for the end of
    // a running step by itself, so this is safe from a callback.
    void Delete() const override {
        for (iDistanceJoint* link : m_links) link->Delete();
        for (iBallJoint* pin : m_pins)
            if (pin) pin->Delete();
        m_group.deleteAll();
        delete this;
    }

private:
    ~Rope() override = default;
    BodyGroup m_group; // the segments
    std::vector<iRigidBody*>& m_segments = m_group.bodies;
    std::vector<iDistanceJoint*> m_links;
    iBallJoint* m_pins[2] = {nullptr, nullptr}; // start, end
};

} // namespace

} // namespace physics

extern "C" iRope* CreateRope(const Vector& start, const Vector& end, int segments, float segmentMass) {
    if (!start.isFinite() || !end.isFinite() || segments < 2 || !(segmentMass > 0) ||
        !std::isfinite(segmentMass)) {
        error(L"CreateRope: needs finite ends, at least 2 segments and a finite mass > 0; refused");
        return nullptr;
    }
    const float spacing = (end - start).length() / float(segments - 1);
    if (!(spacing > 0) || !std::isfinite(spacing) ||
        !isValidInertiaTensor(getSphereInertiaTensor(segmentMass, spacing / 4))) {
        error(L"CreateRope: the segments' spacing and mass give no valid segment (ends too close or too far "
              L"apart for that many segments); refused");
        return nullptr;
    }
    physics::Rope* rope = new physics::Rope(start, end, segments, segmentMass);
    if (!rope->complete()) {
        rope->Delete();
        return nullptr;
    }
    return rope;
}
