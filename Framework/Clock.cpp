// Clock.cpp - the real-time and stepped clocks behind iClock.
#include "iClock.h"

#include <chrono>

namespace {

class RealClock final : public iClock {
public:
    RealClock() : m_start(std::chrono::steady_clock::now()) {}
    void tick() override {}
    int now() const override {
        auto elapsed = std::chrono::steady_clock::now() - m_start;
        return int(std::chrono::duration_cast<std::chrono::milliseconds>(elapsed).count());
    }
    void Delete() const override { delete this; }

private:
    std::chrono::steady_clock::time_point m_start;
};

class SteppedClock final : public iClock {
public:
    SteppedClock(int msPerFrame, int startMs) : m_step(msPerFrame > 0 ? msPerFrame : 1), m_now(startMs) {}
    void tick() override { m_now += m_step; }
    int now() const override { return m_now; }
    void Delete() const override { delete this; }

private:
    int m_step;
    int m_now;
};

} // namespace

extern "C" iClock* CreateRealClock() { return new RealClock(); }
extern "C" iClock* CreateSteppedClock(int msPerFrame, int startMs) {
    return new SteppedClock(msPerFrame, startMs);
}
