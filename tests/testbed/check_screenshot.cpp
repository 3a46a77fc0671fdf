// check_screenshot.cpp - checks the testbed's picture of a box at a known place (ctest testbed.screenshot).
//
// Works out, with its own look-at and perspective arithmetic (the course framework's conventions: y up,
// left-handed, x to the right when looking along +z, a vertical field of view), which pixels the box's
// visible faces cover, and checks that they have the box's colour (any shade of it from 45 % to 100 %: the
// testbed shades faces by their angle to a light) and that background pixels (where the box would be if the
// picture were mirrored, just beside the box, the corners) have the background colour and not the box's.
// Links nothing of the engine or the testbed.
//
// Usage: check_screenshot FILE.ppm EYE TARGET FOVY_DEGREES CENTRE HALF_EXTENTS RRGGBB BACKGROUND_RRGGBB
// (vectors as X,Y,Z). Exit 0 when every pixel checks, 1 when one does not, 2 on bad arguments or file.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

struct V {
    double x, y, z;
};
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator*(V a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V unit(V a) { return a * (1.0 / std::sqrt(dot(a, a))); }

struct Rgb {
    int r, g, b;
};

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> data;
    Rgb at(int x, int y) const {
        const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
        return {data[i], data[i + 1], data[i + 2]};
    }
};

bool readPpm(const char* path, Image& image) {
    std::FILE* f = std::fopen(path, "rb");
    if (!f) return false;
    int maxValue = 0;
    const bool header = std::fscanf(f, "P6 %d %d %d", &image.width, &image.height, &maxValue) == 3 &&
                        maxValue == 255 && image.width > 0 && image.height > 0 && std::fgetc(f) != EOF;
    if (header) {
        image.data.resize(size_t(image.width) * size_t(image.height) * 3);
        const bool whole = std::fread(image.data.data(), 1, image.data.size(), f) == image.data.size();
        std::fclose(f);
        return whole;
    }
    std::fclose(f);
    return false;
}

bool parseV(const char* text, V& v) { return std::sscanf(text, "%lf,%lf,%lf", &v.x, &v.y, &v.z) == 3; }
bool parseRgb(const char* text, Rgb& c) {
    unsigned packed = 0;
    if (std::sscanf(text, "%6x", &packed) != 1) return false;
    c = {int(packed >> 16) & 0xFF, int(packed >> 8) & 0xFF, int(packed) & 0xFF};
    return true;
}

// Is c a shade (45 % to 100 %, within 10 per channel) of body?
bool isShadeOf(Rgb c, Rgb body) {
    const double k = double(c.r + c.g + c.b) / double(body.r + body.g + body.b);
    if (k < 0.45 || k > 1.05) return false;
    return std::fabs(c.r - k * body.r) <= 10 && std::fabs(c.g - k * body.g) <= 10 &&
           std::fabs(c.b - k * body.b) <= 10;
}
bool isColour(Rgb c, Rgb want) {
    return std::abs(c.r - want.r) <= 10 && std::abs(c.g - want.g) <= 10 && std::abs(c.b - want.b) <= 10;
}

struct Camera {
    V eye, forward, right, up;
    double tanHalf, aspect;
    int width, height;
    // The pixel (column, row from the top) that world point p lands in; false when behind the eye or off
    // the picture.
    bool pixel(V p, int& column, int& row) const {
        const V d = p - eye;
        const double depth = dot(d, forward);
        if (depth <= 0) return false;
        const double ndcX = dot(d, right) / depth / (tanHalf * aspect), ndcY = dot(d, up) / depth / tanHalf;
        column = int(std::floor((ndcX + 1) * 0.5 * width));
        row = int(std::floor((1 - ndcY) * 0.5 * height));
        return column >= 0 && column < width && row >= 0 && row < height;
    }
};

} // namespace

int main(int argc, char** argv) {
    Image image;
    V eye{}, target{}, centre{}, half{};
    Rgb body{}, background{};
    if (argc != 9 || !parseV(argv[2], eye) || !parseV(argv[3], target) || !parseV(argv[5], centre) ||
        !parseV(argv[6], half) || !parseRgb(argv[7], body) || !parseRgb(argv[8], background)) {
        std::fputs("usage: check_screenshot FILE.ppm EYE TARGET FOVY_DEGREES CENTRE HALF RRGGBB BG_RRGGBB\n",
                   stderr);
        return 2;
    }
    if (!readPpm(argv[1], image)) {
        std::fprintf(stderr, "check_screenshot: %s is not a whole binary PPM\n", argv[1]);
        return 2;
    }
    Camera cam;
    cam.eye = eye;
    cam.forward = unit(target - eye);
    cam.right = unit(cross(V{0, 1, 0}, cam.forward)); // left-handed: looking along +z, +x is right
    cam.up = cross(cam.forward, cam.right);
    cam.tanHalf = std::tan(std::atof(argv[4]) * M_PI / 360.0);
    cam.width = image.width;
    cam.height = image.height;
    cam.aspect = double(image.width) / double(image.height);

    int failures = 0, checked = 0;
    auto expect = [&](V p, bool wantBody, const char* what) {
        int x = 0, y = 0;
        if (!cam.pixel(p, x, y)) {
            std::printf("FAIL %s: (%.2f, %.2f, %.2f) is not in the picture\n", what, p.x, p.y, p.z);
            ++failures;
            return;
        }
        const Rgb c = image.at(x, y);
        const bool ok = wantBody ? isShadeOf(c, body) : isColour(c, background) && !isShadeOf(c, body);
        ++checked;
        if (!ok) {
            ++failures;
            std::printf("FAIL %s: pixel (%d, %d) is %02X%02X%02X, want %s\n", what, x, y, c.r, c.g, c.b,
                        wantBody ? "a shade of the body's colour" : "the background");
        }
    };
    // Each face that looks at the eye: a 3 x 3 grid of points inside it, away from its edges.
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            V n{0, 0, 0}, u{0, 0, 0}, v{0, 0, 0};
            (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = sign;
            const double h[3] = {half.x, half.y, half.z};
            (axis == 0 ? u.y : axis == 1 ? u.z : u.x) = h[(axis + 1) % 3];
            (axis == 0 ? v.z : axis == 1 ? v.x : v.y) = h[(axis + 2) % 3];
            const V faceCentre = centre + n * h[axis];
            if (dot(n, eye - faceCentre) <= 0) continue;
            // Skip faces seen almost edge-on: they cover too few pixels to sample.
            if (dot(n, unit(eye - faceCentre)) < 0.2) continue;
            for (int i = -1; i <= 1; ++i)
                for (int j = -1; j <= 1; ++j) expect(faceCentre + u * (0.6 * i) + v * (0.6 * j), true, "box");
        }
    // Background: the box's mirror image across x = 0, just beside the box, and above it.
    expect(V{-centre.x, centre.y, centre.z}, false, "mirror image of the box");
    expect(centre - cam.right * (half.x + half.z + 0.3), false, "left of the box");
    expect(centre + cam.up * (half.y + half.z + 0.6), false, "above the box");
    for (int corner = 0; corner < 4; ++corner) {
        const Rgb c = image.at(corner & 1 ? image.width - 1 : 0, corner & 2 ? image.height - 1 : 0);
        ++checked;
        if (!isColour(c, background)) {
            ++failures;
            std::printf("FAIL corner %d is %02X%02X%02X, want the background\n", corner, c.r, c.g, c.b);
        }
    }
    std::printf("%s: %d pixels checked, %d wrong\n", failures ? "FAIL" : "OK", checked, failures);
    return failures ? 1 : 0;
}
