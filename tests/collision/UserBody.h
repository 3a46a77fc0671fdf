// UserBody.h - a game's own iRigidBody, as the collision-only route asks (the seed's "implement the
// iRigidBody interface"): it holds an RBDynamics and nothing else, and tells the collision package when it
// dies. Header-only; the collision tests never use the simulator.
#pragma once

#include "iRigidBody.h"

#include <algorithm>
#include <vector>

class UserBody final : public iRigidBody {
public:
    explicit UserBody(const Vector& position = Vector(), PhysicsType type = PHYS_Falling) {
        m_dynamics.position = position;
        m_dynamics.physicsType = type;
    }
    ~UserBody() { rigidBodyDestroyed(this); }
    iRigidBody* clone() const override { return new UserBody(*this); }
    void attach(iFrame*) override {}
    void attachListener(iCollisionListener* l) override { m_listeners.push_back(l); }
    void detachListener(const iCollisionListener* l) override {
        m_listeners.erase(std::remove(m_listeners.begin(), m_listeners.end(), l), m_listeners.end());
    }
    void restore(int) override {}
    std::vector<iCollisionListener*>& getListeners() override { return m_listeners; }
    iFrame* getFrame() override { return nullptr; }
    RBDynamics& getDynamics() override {
        ++reads;
        return m_dynamics;
    }
    const RBDynamics& getDynamics() const override {
        ++reads;
        return m_dynamics;
    }
    // How often anything read a UserBody's dynamics (what a space reads of the bodies: QueryBatchTest.cpp).
    static inline unsigned long reads = 0;
    void setDynamics(const RBDynamics& d) override { m_dynamics = d; }
    void reset(int) override {}
    void suspend() const override {}
    void release() const override {}
    void Delete() const override { delete this; }

    // Test helpers.
    void place(const Vector& p, const Matrix& r = Matrix(1)) {
        m_dynamics.position = p;
        m_dynamics.orientation = r;
    }

private:
    UserBody(const UserBody& o) : iRigidBody(o), m_dynamics(o.m_dynamics) {}
    RBDynamics m_dynamics;
    std::vector<iCollisionListener*> m_listeners;
};
