// StayOnThisCpu.h - keeps a benchmark process on the CPU it runs on now, so that the figures it sets beside
// each other (engines, body counts) come from the same core. On a shared virtual machine one virtual CPU can
// run the same code 30 % slower than another (2026-11-27, 2 vCPUs, for a while that afternoon: the awake
// pyramid 0.91-1.01 ms a step on one, 1.23-1.30 on the other, every run), and a move between them in the
// middle of a run would be charged to whatever ran then.
#pragma once

#if defined(__linux__)
#include <sched.h>
#endif

// That CPU's number, or -1 where the process cannot be kept on one (not Linux, or refused).
inline int stayOnThisCpu() {
#if defined(__linux__)
    const int cpu = sched_getcpu();
    if (cpu < 0) return -1;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    return sched_setaffinity(0, sizeof one, &one) == 0 ? cpu : -1;
#else
    return -1;
#endif
}
