// OdeScenes.cpp - bench_compare's adapter for ODE (Debian's libode-dev, double precision): a world stepped
// with dWorldQuickStep (20 iterations, ODE's default), a hash space, contacts made in the near callback
// (mu 0.5, no bounce, ODE's default ERP and CFM, up to 4 points a pair), auto-disable only for rows that
// sleep; and for the broadphase row a hash space whose dSpaceCollide is timed with a callback that only
// counts.
#include "Scene.h"

#include <ode/ode.h>

#include <cstring>
#include <string>

namespace compare {

namespace {

constexpr int kMaxContacts = 4;

// dInitODE2 once for the process (dCloseODE is never called: ODE's globals live as long as the program).
void initOnce() {
    static const bool done = [] {
        dInitODE2(0);
        return true;
    }();
    (void)done;
}

void setPose(dGeomID g, const Pose& pose) {
    dMatrix3 R;
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) R[4 * r + k] = dReal(pose.R[3 * r + k]);
        R[4 * r + 3] = 0;
    }
    dGeomSetPosition(g, dReal(pose.p[0]), dReal(pose.p[1]), dReal(pose.p[2]));
    dGeomSetRotation(g, R);
}

dGeomID createGeom(dSpaceID space, const BodyDesc& b) {
    const dReal s = dReal(b.size);
    return b.shape == Shape::Sphere ? dCreateSphere(space, s) : dCreateBox(space, 2 * s, 2 * s, 2 * s);
}

class OdeSim : public Sim {
public:
    OdeSim(const SceneDesc& s, const SimOptions& o) {
        initOnce();
        m_world = dWorldCreate();
        m_space = dHashSpaceCreate(nullptr);
        m_contacts = dJointGroupCreate(0);
        dWorldSetGravity(m_world, 0, dReal(-9.81), 0);
        if (o.iterations > 0) dWorldSetQuickStepNumIterations(m_world, o.iterations);
        dWorldSetAutoDisableFlag(m_world, o.sleeping ? 1 : 0);
        if (s.ground) dCreatePlane(m_space, 0, 1, 0, 0);
        for (const BodyDesc& b : s.bodies) {
            dBodyID body = dBodyCreate(m_world);
            dGeomID geom = createGeom(m_space, b);
            dGeomSetBody(geom, body);
            dMass mass;
            if (b.shape == Shape::Sphere)
                dMassSetSphereTotal(&mass, dReal(b.mass), dReal(b.size));
            else
                dMassSetBoxTotal(&mass, dReal(b.mass), dReal(2 * b.size), dReal(2 * b.size),
                                 dReal(2 * b.size));
            dBodySetMass(body, &mass);
            setPose(geom, b.pose); // moves the body
            m_bodies.push_back(body);
        }
    }
    ~OdeSim() override {
        dJointGroupDestroy(m_contacts);
        dSpaceDestroy(m_space); // destroys its geoms (cleanup mode on by default)
        dWorldDestroy(m_world); // destroys its bodies
    }
    OdeSim(const OdeSim&) = delete;
    OdeSim& operator=(const OdeSim&) = delete;

    void step() override {
        dSpaceCollide(m_space, this, &OdeSim::near);
        dWorldQuickStep(m_world, dReal(kDt));
        dJointGroupEmpty(m_contacts);
    }
    BodyState state(size_t i) const override {
        BodyState s;
        const dReal* p = dBodyGetPosition(m_bodies[i]);
        const dReal* R = dBodyGetRotation(m_bodies[i]);
        const dReal* v = dBodyGetLinearVel(m_bodies[i]);
        for (int r = 0; r < 3; ++r) {
            s.pose.p[r] = p[r];
            s.v[r] = v[r];
            for (int k = 0; k < 3; ++k) s.pose.R[3 * r + k] = R[4 * r + k];
        }
        return s;
    }
    size_t bodyCount() const override { return m_bodies.size(); }

private:
    static void near(void* data, dGeomID a, dGeomID b) {
        OdeSim* self = static_cast<OdeSim*>(data);
        dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
        if (!ba && !bb) return;
        // Skip pairs whose bodies are both disabled (asleep); ODE's own examples do the same.
        if ((!ba || !dBodyIsEnabled(ba)) && (!bb || !dBodyIsEnabled(bb))) return;
        dContact contact[kMaxContacts];
        std::memset(contact, 0, sizeof(contact));
        int n = dCollide(a, b, kMaxContacts, &contact[0].geom, sizeof(dContact));
        for (int i = 0; i < n; ++i) {
            contact[i].surface.mode = dContactApprox1;
            contact[i].surface.mu = dReal(kFriction);
            contact[i].surface.bounce = 0;
            dJointID j = dJointCreateContact(self->m_world, self->m_contacts, &contact[i]);
            dJointAttach(j, ba, bb);
        }
    }

    dWorldID m_world;
    dSpaceID m_space;
    dJointGroupID m_contacts;
    std::vector<dBodyID> m_bodies;
};

class OdePairs : public PairFinder {
public:
    explicit OdePairs(const SceneDesc& s) {
        initOnce();
        m_space = dHashSpaceCreate(nullptr);
        for (const BodyDesc& b : s.bodies) {
            dGeomID g = createGeom(m_space, b);
            setPose(g, b.pose);
            m_geoms.push_back(g);
        }
    }
    ~OdePairs() override { dSpaceDestroy(m_space); }
    OdePairs(const OdePairs&) = delete;
    OdePairs& operator=(const OdePairs&) = delete;

    void place(const std::vector<Pose>& poses) override {
        for (size_t i = 0; i < poses.size() && i < m_geoms.size(); ++i) setPose(m_geoms[i], poses[i]);
    }
    size_t findPairs() override {
        size_t pairs = 0;
        dSpaceCollide(m_space, &pairs, [](void* data, dGeomID, dGeomID) { ++*static_cast<size_t*>(data); });
        return pairs;
    }

private:
    dSpaceID m_space;
    std::vector<dGeomID> m_geoms;
};

} // namespace

EngineInfo odeInfo() {
    initOnce();
    EngineInfo info;
    info.name = "ODE";
    info.precision = dCheckConfiguration("ODE_double_precision") ? "double" : "float";
    info.defaults = "dWorldQuickStep, 20 iterations, hash space, ERP 0.2, CFM 1e-5, dContactApprox1, " +
                    std::to_string(kMaxContacts) + " contacts a pair; config: " + dGetConfiguration();
    info.knob = "dWorldSetQuickStepNumIterations";
    info.pairsNote = "dSpaceCollide on a hash space, callback counts (counts AABB pairs)";
    info.ladder = {5, 10, 20, 40, 80, 160};
    return info;
}

std::unique_ptr<Sim> makeOdeSim(const SceneDesc& scene, const SimOptions& options) {
    return std::make_unique<OdeSim>(scene, options);
}

std::unique_ptr<PairFinder> makeOdePairs(const SceneDesc& scene) { return std::make_unique<OdePairs>(scene); }

} // namespace compare
