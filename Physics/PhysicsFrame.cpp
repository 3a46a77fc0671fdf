// PhysicsFrame.cpp - a Frame that owns a RigidBody bound to itself (CreatePhysicsFrame).
//
// Ownership: the PhysicsFrame owns its body. The scene never deletes a PhysicsFrame's body: deleting the
// scene first only takes the body out of it (the frame keeps working, unsimulated), and Delete() on the
// body itself is refused. PhysicsFrame::Delete deletes the body (deferred to the end of the step when called
// during an update; the body lets go of the frame at once) and then the frame.
#include "PhysicsScene.h"
#include "RigidBody.h"
#include "iPhysicsFrame.h"
#include "iUtilities.h"

#include <vector>

namespace physics {

class PhysicsFrame;
namespace {
// PhysicsFrames by the frame they are attached to: a Frame keeps no list of its children, so that deleting a
// PhysicsFrame can re-root the PhysicsFrames attached to it instead of leaving them a dangling parent.
std::unordered_multimap<const iFrame*, PhysicsFrame*>& children() {
    static std::unordered_multimap<const iFrame*, PhysicsFrame*> all;
    return all;
}
void unlistChild(const iFrame* parent, PhysicsFrame* child) {
    auto range = children().equal_range(parent);
    for (auto it = range.first; it != range.second; ++it)
        if (it->second == child) {
            children().erase(it);
            return;
        }
}
// The parent a frame has after attachTo(asked): the framework's answer where its frames tell their parent
// (the stand-in's do, and it refuses a cycle), otherwise the one asked for (a course framework's attachTo
// does not refuse).
template <class F> auto parentAfterAttach(const F& f, iFrame*, int) -> decltype(f.parent()) {
    return f.parent();
}
template <class F> iFrame* parentAfterAttach(const F&, iFrame* asked, long) { return asked; }
} // namespace

class PhysicsFrame final : public iPhysicsFrame {
public:
    PhysicsFrame() : m_body(new RigidBody(this)) {
        m_body->setOwner(this);
        if (PhysicsScene* scene = PhysicsScene::active()) scene->add(m_body);
    }
    PhysicsFrame(const PhysicsFrame&) = delete;
    PhysicsFrame& operator=(const PhysicsFrame&) = delete;

    iRigidBody* getRB() const override { return m_body; }
    RBDynamics* getDynamics() const override { return &m_body->getDynamics(); }

    // A new frame at the body's pose, owning a copy of the body (dynamics, listeners, generators) in the same
    // scene as this one's; an attached body's copy joins the same composite. (A course framework's Frame does
    // not expose its parent, so the new frame is a root frame.)
    iPhysicsFrame* clone() const override {
        PhysicsFrame* copy = new PhysicsFrame();
        RigidBody* b = copy->m_body;
        if (b->scene() != m_body->scene()) {
            if (b->scene()) b->scene()->remove(b);
            if (m_body->scene()) m_body->scene()->add(b);
        }
        b->getDynamics() = m_body->getDynamics();
        const RBDynamics& src = m_body->getDynamics();
        if (src.attachedTo()) { // a copy starts unattached: at the original's world pose and velocity...
            RBDynamics& d = b->getDynamics();
            d.position = src.getWorldPosition();
            d.orientation = src.getWorldOrientation();
            d.velocity = src.getVelocityAtWorldPoint(d.position);
            d.angularVelocity = src.attachmentRoot()->angularVelocity;
            d.attachTo(src.attachedTo()); // ...then in the same composite
        }
        b->getListeners() = m_body->getListeners();
        b->generators() = m_body->generators();
        b->copySwitches(*m_body);
        b->inheritLastValid(*m_body);
        b->attach(copy); // the frame takes the copied body's pose
        return copy;
    }
    // The seed: attaching a PhysicsFrame to another also attaches its body to that frame's body (one
    // composite, RBDynamics::attachTo); attaching to a plain frame or to nullptr detaches the body. Refused
    // with error(), changing nothing, when either the frames or the bodies would form a cycle.
    void attachTo(iFrame* parent) override {
        auto* pf = dynamic_cast<PhysicsFrame*>(parent);
        RBDynamics& d = m_body->getDynamics();
        for (const RBDynamics* a = pf ? &pf->m_body->getDynamics() : nullptr; a; a = a->attachedTo()) {
            if (a == &d) {
                error(L"PhysicsFrame::attachTo: the parent's body is attached to this one's; refused");
                return;
            }
        }
        m_body->adoptFrameEdits(); // moves the game made to either frame count before the bodies link
        if (pf) pf->m_body->adoptFrameEdits();
        if (m_listedUnder) unlistChild(m_listedUnder, this);
        Frame::attachTo(parent);
        m_listedUnder = parentAfterAttach(*this, parent, 0);
        if (m_listedUnder) children().emplace(m_listedUnder, this);
        d.attachTo(pf ? &pf->m_body->getDynamics() : nullptr);
        m_body->attach(this); // T re-expressed against the new parent, at the body's pose
    }
    void suspend() const override {}
    void release() const override {}
    // Deleting a PhysicsFrame first is safe for what it can know of: PhysicsFrames attached to it become root
    // frames at their world pose (their bodies stay attached to this one's until it is gone), and bodies
    // bound to it with attach() let go of it. Plain frames attached to it cannot be told (README).
    void Delete() const override {
        auto* self = const_cast<PhysicsFrame*>(this);
        if (m_listedUnder) unlistChild(m_listedUnder, self);
        std::vector<PhysicsFrame*> kids;
        auto range = children().equal_range(this);
        for (auto it = range.first; it != range.second; ++it) kids.push_back(it->second);
        children().erase(this);
        for (PhysicsFrame* k : kids) {
            k->Frame::attachTo(nullptr);
            k->m_listedUnder = nullptr;
        }
        RigidBody::frameDeleted(this);
        m_body->setOwner(nullptr);
        m_body->Delete(); // unbinds this frame now, even when the deletion itself is deferred
        delete this;
    }

private:
    ~PhysicsFrame() override = default;
    RigidBody* m_body;
    // The frame this one is listed under in children(): the course framework's Frame does not expose its
    // parent to a derived class.
    iFrame* m_listedUnder = nullptr;
};

} // namespace physics

extern "C" iPhysicsFrame* CreatePhysicsFrame() {
    if (!physics::PhysicsScene::active()) // the seed's order is scene first: say so while it can be fixed
        error(L"CreatePhysicsFrame: no physics scene exists yet, so its body is not simulated; add() getRB() "
              L"to a scene once there is one");
    return new physics::PhysicsFrame();
}
