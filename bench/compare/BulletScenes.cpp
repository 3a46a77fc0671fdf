// BulletScenes.cpp - bench_compare's adapter for Bullet (Debian's libbullet-dev, float): a
// btDiscreteDynamicsWorld at its defaults (btDbvtBroadphase, sequential impulse solver, 10 iterations)
// stepping a SceneDesc at 1/60 s, and for the broadphase row a btCollisionWorld whose AABB update and
// overlapping-pair calculation are timed (no narrow phase).
#include "Scene.h"

#include <btBulletCollisionCommon.h>
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <string>

namespace compare {

namespace {

// Bullet combines friction as the product of the two objects' values: sqrt(0.5) each gives 0.5.
const btScalar kObjectFriction = btScalar(std::sqrt(kFriction));

btTransform transformOf(const Pose& pose) {
    auto f = [](double x) { return static_cast<btScalar>(x); };
    const double* R = pose.R;
    const btMatrix3x3 basis(f(R[0]), f(R[1]), f(R[2]), f(R[3]), f(R[4]), f(R[5]), f(R[6]), f(R[7]), f(R[8]));
    return btTransform(basis, btVector3(f(pose.p[0]), f(pose.p[1]), f(pose.p[2])));
}

Pose poseOf(const btTransform& t) {
    Pose pose;
    for (int r = 0; r < 3; ++r) {
        pose.p[r] = t.getOrigin()[r];
        for (int k = 0; k < 3; ++k) pose.R[3 * r + k] = t.getBasis()[r][k];
    }
    return pose;
}

// The shapes a scene uses, one per distinct size (shared by all bodies of that size).
class Shapes {
public:
    btCollisionShape* get(const BodyDesc& b) {
        for (auto& s : m_list)
            if (s.first.shape == b.shape && s.first.size == b.size) return s.second.get();
        btCollisionShape* shape = nullptr;
        if (b.shape == Shape::Sphere)
            shape = new btSphereShape(btScalar(b.size));
        else
            shape = new btBoxShape(btVector3(btScalar(b.size), btScalar(b.size), btScalar(b.size)));
        BodyDesc key = b;
        m_list.emplace_back(key, std::unique_ptr<btCollisionShape>(shape));
        return shape;
    }

private:
    std::vector<std::pair<BodyDesc, std::unique_ptr<btCollisionShape>>> m_list;
};

class BulletSim : public Sim {
public:
    BulletSim(const SceneDesc& s, const SimOptions& o)
        : m_dispatcher(&m_config), m_world(&m_dispatcher, &m_broadphase, &m_solver, &m_config),
          m_ground(btVector3(0, 1, 0), 0) {
        m_world.setGravity(btVector3(0, btScalar(-9.81), 0));
        if (o.iterations > 0) m_world.getSolverInfo().m_numIterations = o.iterations;
        if (s.ground) {
            btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, &m_ground);
            info.m_friction = kObjectFriction;
            info.m_restitution = 0;
            m_groundBody = std::make_unique<btRigidBody>(info);
            m_world.addRigidBody(m_groundBody.get());
        }
        for (const BodyDesc& b : s.bodies) {
            btCollisionShape* shape = m_shapes.get(b);
            btVector3 inertia(0, 0, 0);
            shape->calculateLocalInertia(btScalar(b.mass), inertia);
            btRigidBody::btRigidBodyConstructionInfo info(btScalar(b.mass), nullptr, shape, inertia);
            info.m_startWorldTransform = transformOf(b.pose);
            info.m_friction = kObjectFriction;
            info.m_restitution = 0;
            auto body = std::make_unique<btRigidBody>(info);
            if (!o.sleeping) body->setActivationState(DISABLE_DEACTIVATION);
            m_world.addRigidBody(body.get());
            m_bodies.push_back(std::move(body));
        }
    }
    ~BulletSim() override {
        for (auto& b : m_bodies) m_world.removeRigidBody(b.get());
        if (m_groundBody) m_world.removeRigidBody(m_groundBody.get());
    }
    void step() override {
        m_world.stepSimulation(btScalar(kDt), 0);
    } // maxSubSteps 0: exactly one step of dt
    BodyState state(size_t i) const override {
        BodyState s;
        s.pose = poseOf(m_bodies[i]->getWorldTransform());
        const btVector3& v = m_bodies[i]->getLinearVelocity();
        for (int k = 0; k < 3; ++k) s.v[k] = v[k];
        return s;
    }
    size_t bodyCount() const override { return m_bodies.size(); }

private:
    btDefaultCollisionConfiguration m_config;
    btCollisionDispatcher m_dispatcher;
    btDbvtBroadphase m_broadphase;
    btSequentialImpulseConstraintSolver m_solver;
    btDiscreteDynamicsWorld m_world;
    btStaticPlaneShape m_ground;
    Shapes m_shapes;
    std::unique_ptr<btRigidBody> m_groundBody;
    std::vector<std::unique_ptr<btRigidBody>> m_bodies;
};

class BulletPairs : public PairFinder {
public:
    explicit BulletPairs(const SceneDesc& s)
        : m_dispatcher(&m_config), m_world(&m_dispatcher, &m_broadphase, &m_config) {
        for (const BodyDesc& b : s.bodies) {
            auto object = std::make_unique<btCollisionObject>();
            object->setCollisionShape(m_shapes.get(b));
            object->setWorldTransform(transformOf(b.pose));
            m_world.addCollisionObject(object.get());
            m_objects.push_back(std::move(object));
        }
    }
    ~BulletPairs() override {
        for (auto& o : m_objects) m_world.removeCollisionObject(o.get());
    }
    void place(const std::vector<Pose>& poses) override {
        for (size_t i = 0; i < poses.size() && i < m_objects.size(); ++i)
            m_objects[i]->setWorldTransform(transformOf(poses[i]));
    }
    size_t findPairs() override {
        m_world.updateAabbs();             // the DBVT leaves follow the moved objects
        m_world.computeOverlappingPairs(); // m_broadphase.calculateOverlappingPairs(dispatcher)
        return size_t(m_broadphase.getOverlappingPairCache()->getNumOverlappingPairs());
    }

private:
    btDefaultCollisionConfiguration m_config;
    btCollisionDispatcher m_dispatcher;
    btDbvtBroadphase m_broadphase;
    btCollisionWorld m_world;
    Shapes m_shapes;
    std::vector<std::unique_ptr<btCollisionObject>> m_objects;
};

} // namespace

EngineInfo bulletInfo() {
    EngineInfo info;
    info.name = "Bullet";
    info.precision = sizeof(btScalar) == 8 ? "double" : "float";
    info.defaults = "btDiscreteDynamicsWorld, btDbvtBroadphase, sequential impulse, 10 solver iterations, "
                    "split impulse " +
                    std::string(btContactSolverInfo().m_splitImpulse ? "on" : "off") + ", version " +
                    std::to_string(btGetVersion());
    info.knob = "m_numIterations";
    info.pairsNote =
        "btCollisionWorld::updateAabbs + computeOverlappingPairs (btDbvtBroadphase; counts AABB pairs)";
    info.ladder = {2, 4, 6, 10, 15, 20, 30, 50, 80};
    return info;
}

std::unique_ptr<Sim> makeBulletSim(const SceneDesc& scene, const SimOptions& options) {
    return std::make_unique<BulletSim>(scene, options);
}

std::unique_ptr<PairFinder> makeBulletPairs(const SceneDesc& scene) {
    return std::make_unique<BulletPairs>(scene);
}

} // namespace compare
