// StepProfiler.h - times the phases of a scene's steps into the PhysicsProfile its game reads
// (iPhysicsSceneProfile.h): one tick reading per phase, each phase's time the ticks since the last reading.
//
// A tick is the CPU's time-stamp counter where it has one (x86), else the steady clock's nanoseconds: in a
// virtual machine, reading the steady clock for every phase was 2.9 % of a two-body step's samples, and twice
// an update 0.45 % (perf). The steady clock times the whole update, and each phase gets its share of the
// update's ticks of that time: no tick rate to know, and the phases add up to the update.
#pragma once

#include "iPhysicsSceneProfile.h"

#include <chrono>
#include <cstdint>

#if defined(__x86_64__) || defined(__i386__) || defined(_M_X64)
#define GUARDIAN_PROFILE_TSC 1
#if defined(_MSC_VER)
#include <intrin.h>
#else
#include <x86intrin.h>
#endif
#else
#define GUARDIAN_PROFILE_TSC 0
#endif

namespace physics {

class StepProfiler {
public:
    using Phase = double PhysicsProfile::*;

    void beginUpdate() {
        m_current = PhysicsProfile();
        m_updateStart = Clock::now();
        m_startTicks = m_last = ticks();
    }
    // The ticks since the last reading go to phase (turned into seconds by endUpdate).
    void lap(Phase phase) {
        const std::uint64_t now = ticks();
        // (A thread moved to a core whose counter is behind: nothing, rather than 2^64 ticks.)
        m_current.*phase += now > m_last ? double(now - m_last) : 0.0;
        m_last = now;
    }
    // The counts at the end of the update's steps.
    PhysicsProfile& current() { return m_current; }
    // Closes the update: it becomes the profile read if it stepped.
    void endUpdate() {
        const double seconds = std::chrono::duration<double>(Clock::now() - m_updateStart).count();
        const std::uint64_t ticksNow = ticks();
        const double perTick = ticksNow > m_startTicks ? seconds / double(ticksNow - m_startTicks) : 0.0;
        for (Phase phase : {&PhysicsProfile::updaters, &PhysicsProfile::edits, &PhysicsProfile::collision,
                            &PhysicsProfile::islands, &PhysicsProfile::integration, &PhysicsProfile::solver,
                            &PhysicsProfile::continuous, &PhysicsProfile::sleeping, &PhysicsProfile::events})
            m_current.*phase *= perTick;
        m_current.total = seconds;
        if (m_current.steps > 0) m_profile = m_current;
    }
    const PhysicsProfile& profile() const { return m_profile; }

private:
    using Clock = std::chrono::steady_clock;
    static std::uint64_t ticks() {
#if GUARDIAN_PROFILE_TSC
        return __rdtsc();
#else
        return std::uint64_t(
            std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count());
#endif
    }
    PhysicsProfile m_profile, m_current;
    Clock::time_point m_updateStart;
    std::uint64_t m_startTicks = 0, m_last = 0;
};

} // namespace physics
