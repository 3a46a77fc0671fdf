// SolverFixtures.h - hand-made bodies and geometries for testing the contact solver without a space.
#pragma once

#include "ContactSolver.h"
#include "iCollisionGeometry.h"
#include "iCollisionSpace.h"
#include "iRigidBody.h"

#include <vector>

namespace solver_test {

class Body final : public iRigidBody {
public:
    RBDynamics d;
    std::vector<iCollisionListener*> listeners;
    iRigidBody* clone() const override { return nullptr; }
    void attach(iFrame*) override {}
    void attachListener(iCollisionListener*) override {}
    void detachListener(const iCollisionListener*) override {}
    void restore(int) override {}
    std::vector<iCollisionListener*>& getListeners() override { return listeners; }
    iFrame* getFrame() override { return nullptr; }
    RBDynamics& getDynamics() override { return d; }
    const RBDynamics& getDynamics() const override { return d; }
    void setDynamics(const RBDynamics& x) override { d = x; }
    void reset(int) override {}
    void suspend() const override {}
    void release() const override {}
    void Delete() const override {}
};

// A geometry that only knows its body: the solver needs nothing else.
class Geometry final : public iCollisionGeometry {
public:
    explicit Geometry(iRigidBody* b) : body(b) {}
    iRigidBody* body;
    iCollisionGeometry* clone() const override { return nullptr; }
    void attach(iRigidBody* rb) override { body = rb; }
    iRigidBody* getRigidBody() override { return body; }
    const iRigidBody* getRigidBody() const override { return body; }
    int getCollisionType() const override { return 0; }
    float getBoundingRadius() const override { return 0; }
    void getProjectionBounds(const Vector&, float& lo, float& hi) const override { lo = hi = 0; }
    iCollisionSpace* getSpace() const override { return nullptr; }
    void suspend() const override {}
    void release() const override {}
    void Delete() const override {}
};

inline CollisionContact contact(Geometry& g1, Geometry& g2, const Vector& pos, const Vector& normal,
                                float depth) {
    return CollisionContact{pos, normal, depth, &g1, &g2};
}

} // namespace solver_test
