// check_sample.cpp - runs README's first program and checks what it prints against the analytic projectile,
// not against the simulator: a ball thrown at 5 m/s along z from 10 m, under g = 9.81 m/s^2.
//
// Semi-implicit Euler (v += g dt, then x += v dt) after n steps of dt puts the ball at
//   y_n = y0 - g dt^2 (1 + 2 + ... + n) = y0 - g t^2 / 2 - g t dt / 2,   t = n dt,
// below the exact parabola by g t dt / 2 (8.2 cm after 1 s at 60 Hz), while z = v t is exact. The drawn
// object is interpolated between the last two steps; after a whole number of steps it is exactly one step
// behind, at t - dt.
//
// Usage: readme_sample_check <readme_sample executable>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

const double kG = 9.81, kY0 = 10.0, kVz = 5.0, kDt = 1.0 / 60.0;
const double kPrinted = 0.0015; // printed to 1 mm (0.5 mm rounding) plus float round-off

// Where semi-implicit Euler puts the ball after time t (a whole number of steps).
double eulerY(double t) { return kY0 - kG * t * t / 2 - kG * t * kDt / 2; }

int failures = 0;
void expectNear(const char* what, double got, double want, double tolerance) {
    bool ok = std::fabs(got - want) <= tolerance;
    std::printf("%s %s: %.4f, want %.4f +- %.4f\n", ok ? "ok  " : "FAIL", what, got, want, tolerance);
    if (!ok) ++failures;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: readme_sample_check <readme_sample executable>\n");
        return 2;
    }
    std::FILE* pipe = popen(argv[1], "r");
    if (!pipe) {
        std::perror("popen");
        return 1;
    }
    std::string out;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    int status = pclose(pipe);
    std::printf("the sample printed:\n%s", out.c_str());
    if (status != 0) {
        std::printf("FAIL the sample exited with status %d\n", status);
        return 1;
    }

    double t, x, y, z, dx, dy, dz;
    if (std::sscanf(out.c_str(),
                    "after %lf s the ball is at (%lf, %lf, %lf) m\nand is drawn at (%lf, %lf, %lf) m", &t, &x,
                    &y, &z, &dx, &dy, &dz) != 7) {
        std::printf("FAIL the output is not the two lines README shows\n");
        return 1;
    }
    expectNear("time: 60 steps of 1/60 s", t, 1.0, 0.0005);
    expectNear("x (no force along x)", x, 0.0, kPrinted);
    expectNear("z = vz t (exact under any integrator)", z, kVz * t, kPrinted);
    expectNear("y = y0 - g t^2/2 - g t dt/2 (semi-implicit Euler)", y, eulerY(t), kPrinted);
    // The same y is off the exact parabola by the method's first-order error, g t dt / 2.
    expectNear("exact parabola - y = g t dt / 2", (kY0 - kG * t * t / 2) - y, kG * t * kDt / 2, kPrinted);
    expectNear("drawn x", dx, 0.0, kPrinted);
    expectNear("drawn z = vz (t - dt), one step behind", dz, kVz * (t - kDt), kPrinted);
    expectNear("drawn y = y(t - dt), one step behind", dy, eulerY(t - kDt), kPrinted);
    return failures ? 1 : 0;
}
