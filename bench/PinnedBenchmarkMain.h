// PinnedBenchmarkMain.h - the main() of our Google Benchmark programs: the process stays on the CPU it
// starts on (StayOnThisCpu.h), so that the figures a run sets beside each other come from one core, and the
// context header printed before the results says which (or that it could not).
#pragma once

#include "StayOnThisCpu.h"

#include <benchmark/benchmark.h>

#include <string>

// Keeps the process on its CPU and notes it in the benchmark context; call before benchmark::Initialize.
inline int stayOnThisCpuAndSayWhich() {
    const int cpu = stayOnThisCpu();
    benchmark::AddCustomContext("kept on",
                                cpu >= 0 ? "CPU " + std::to_string(cpu) : "no one CPU (not pinned)");
    return cpu;
}

// BENCHMARK_MAIN(), kept on one CPU.
#define GUARDIAN_PINNED_BENCHMARK_MAIN()                                                                     \
    int main(int argc, char** argv) {                                                                        \
        stayOnThisCpuAndSayWhich();                                                                          \
        benchmark::Initialize(&argc, argv);                                                                  \
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;                                    \
        benchmark::RunSpecifiedBenchmarks();                                                                 \
        benchmark::Shutdown();                                                                               \
        return 0;                                                                                            \
    }
