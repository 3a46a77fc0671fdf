// StepProfiler.h - times the phases of a scene's steps into the PhysicsProfile its game reads
// (iPhysicsSceneProfile.h): one clock reading per phase, each phase's time the gap since the last reading.
#pragma once

#include "iPhysicsSceneProfile.h"

#include <chrono>

namespace physics {

class StepProfiler {
public:
    using Phase = double PhysicsProfile::*;

    void beginUpdate() {
        m_current = PhysicsProfile();
        m_updateStart = m_last = Clock::now();
    }
    // The time since the last reading goes to phase.
    void lap(Phase phase) {
        const Clock::time_point now = Clock::now();
        m_current.*phase += std::chrono::duration<double>(now - m_last).count();
        m_last = now;
    }
    // The counts at the end of the update's steps.
    PhysicsProfile& current() { return m_current; }
    // Closes the update: it becomes the profile read if it stepped.
    void endUpdate() {
        m_current.total = std::chrono::duration<double>(Clock::now() - m_updateStart).count();
        if (m_current.steps > 0) m_profile = m_current;
    }
    const PhysicsProfile& profile() const { return m_profile; }

private:
    using Clock = std::chrono::steady_clock;
    PhysicsProfile m_profile, m_current;
    Clock::time_point m_updateStart, m_last;
};

} // namespace physics
