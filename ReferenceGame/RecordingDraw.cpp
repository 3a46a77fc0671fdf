// RecordingDraw.cpp - drawing a recorded frame as the live space and scene draw themselves. Each step below
// repeats the engine's (Collision/SpaceDebugDraw.cpp, Physics/SceneDebugDraw.cpp, the geometries'
// worldShapes) operation for operation: the pictures must match byte for byte, so the float arithmetic must.
#include "RecordingDraw.h"

#include "MathDefinitions.h"

#include <cmath>

namespace {

// SpaceDebugDraw.cpp's and SceneDebugDraw.cpp's sizes.
constexpr float kRecDrawContactPointSize = 0.1f;
constexpr float kRecDrawContactNormalLength = 0.5f;
constexpr int kRecDrawPlaneCells = 10;
constexpr float kRecDrawMinPlaneHalfSize = 2.0f;
const char* const kRecDrawSleepMark = "zz";

// A shape at its recorded pose, as the geometry's worldShapes makes it.
struct RecDrawShape {
    RecordedShape::Kind kind;
    Vector centre, axis[3], half; // Sphere: half.x is the radius; Plane: axis[0] is the normal
    float offset;
    DebugColour colour;
};

struct RecDrawBounds {
    Vector min, max;
    bool bounded = false;
    void grow(const Vector& lo, const Vector& hi) { // as spaceDrawGrow
        if (!bounded) {
            min = lo, max = hi, bounded = true;
            return;
        }
        min = Vector(std::fmin(min.x, lo.x), std::fmin(min.y, lo.y), std::fmin(min.z, lo.z));
        max = Vector(std::fmax(max.x, hi.x), std::fmax(max.y, hi.y), std::fmax(max.z, hi.z));
    }
};

float recDrawProjectedRadius(const RecDrawShape& b, const Vector& n) { // gcol::boxProjectedRadius
    return b.half.x * std::fabs(dot(b.axis[0], n)) + b.half.y * std::fabs(dot(b.axis[1], n)) +
           b.half.z * std::fabs(dot(b.axis[2], n));
}

void recDrawGrow(RecDrawBounds& bounds, const RecDrawShape& s) { // gcol::shapeAabb
    if (s.kind == RecordedShape::Sphere) {
        const Vector r(s.half.x, s.half.x, s.half.x);
        bounds.grow(s.centre - r, s.centre + r);
    } else if (s.kind == RecordedShape::Box) {
        const Vector e(recDrawProjectedRadius(s, Vector(1, 0, 0)), recDrawProjectedRadius(s, Vector(0, 1, 0)),
                       recDrawProjectedRadius(s, Vector(0, 0, 1)));
        bounds.grow(s.centre - e, s.centre + e);
    }
}

// spaceDrawPlane: a grid under the rest of the scene, and a short line along the normal.
void recDrawPlane(iDebugDraw& out, const RecDrawShape& p, const RecDrawBounds& scene) {
    const Vector n = p.axis[0];
    const Vector pick = std::fabs(n.x) < 0.9f ? Vector(1, 0, 0) : Vector(0, 1, 0);
    const Vector u = (pick - n * dot(pick, n)).normalize();
    const Vector v = cross(n, u);
    float lo[2] = {0, 0}, hi[2] = {0, 0};
    for (int i = 0; scene.bounded && i < 8; ++i) {
        const Vector corner(i & 1 ? scene.max.x : scene.min.x, i & 2 ? scene.max.y : scene.min.y,
                            i & 4 ? scene.max.z : scene.min.z);
        const float a = dot(corner, u), b = dot(corner, v);
        lo[0] = i ? std::fmin(lo[0], a) : a, hi[0] = i ? std::fmax(hi[0], a) : a;
        lo[1] = i ? std::fmin(lo[1], b) : b, hi[1] = i ? std::fmax(hi[1], b) : b;
    }
    const float margin = std::fmax(1.0f, 0.1f * std::fmax(hi[0] - lo[0], hi[1] - lo[1]));
    float half[2], mid[2];
    for (int k = 0; k < 2; ++k) {
        mid[k] = 0.5f * (lo[k] + hi[k]);
        half[k] = std::ceil(std::fmax(kRecDrawMinPlaneHalfSize, 0.5f * (hi[k] - lo[k]) + margin));
    }
    const Vector centre = u * mid[0] + v * mid[1] + n * p.offset;
    const float cellU = 2.0f * half[0] / float(kRecDrawPlaneCells),
                cellV = 2.0f * half[1] / float(kRecDrawPlaneCells);
    for (int i = 0; i <= kRecDrawPlaneCells; ++i) {
        const float a = -half[0] + cellU * float(i), b = -half[1] + cellV * float(i);
        out.drawLine(centre + u * a - v * half[1], centre + u * a + v * half[1], p.colour);
        out.drawLine(centre + v * b - u * half[0], centre + v * b + u * half[0], p.colour);
    }
    out.drawLine(centre, centre + n * std::fmin(cellU, cellV), p.colour);
}

DebugColour recDrawColour(const RecordedBody& b, unsigned flags) { // spaceDrawColour
    if (b.fixed()) return debugcolour::kFixed;
    if ((flags & DEBUGDRAW_Sleeping) && b.asleep()) return debugcolour::kSleeping;
    return debugcolour::kShape;
}

} // namespace

void drawRecordedFrame(iDebugDraw& out, const std::vector<RecordedShape>& shapes, const RecordedFrame& f,
                       unsigned flags) {
    std::vector<RecDrawShape> drawn;
    RecDrawBounds scene;
    for (const RecordedShape& s : shapes) {
        if (s.body >= 0 && size_t(s.body) >= f.bodies.size()) continue; // not built yet at this frame
        RecDrawShape d{s.kind, Vector(), {}, s.size, s.offset, debugcolour::kFixed};
        if (s.kind == RecordedShape::Plane) { // bodiless: CPlane::worldShapes at the identity pose
            d.axis[0] = Matrix(1).direction(s.size).normalize();
            d.offset = s.offset + dot(d.axis[0], Vector());
        } else {
            const RecordedBody& b = f.bodies[size_t(s.body)];
            d.centre = b.origin;
            d.colour = recDrawColour(b, flags);
            for (int i = 0; i < 3; ++i) d.axis[i] = b.rotation.direction(char('x' + i)).normalize(); // COBB
            recDrawGrow(scene, d);
        }
        drawn.push_back(d);
    }
    if (flags & DEBUGDRAW_Shapes) {
        for (const RecDrawShape& d : drawn) {
            if (d.kind == RecordedShape::Plane) {
                recDrawPlane(out, d, scene);
            } else if (d.kind == RecordedShape::Sphere) {
                out.drawWireSphere(d.centre, d.half.x, d.colour);
            } else {
                const Matrix r(d.axis[0].x, d.axis[0].y, d.axis[0].z, 0, d.axis[1].x, d.axis[1].y,
                               d.axis[1].z, 0, d.axis[2].x, d.axis[2].y, d.axis[2].z, 0, 0, 0, 0, 1);
                out.drawWireBox(d.centre, d.half, r, d.colour);
            }
        }
    }
    for (const RecordedContact& c : f.contacts) {
        if (flags & DEBUGDRAW_ContactPoints)
            out.drawPoint(c.point, kRecDrawContactPointSize, debugcolour::kContact);
        if (flags & DEBUGDRAW_ContactNormals)
            out.drawLine(c.point, c.point + c.normal * kRecDrawContactNormalLength, debugcolour::kContact);
    }
    // The scene's part: "zz" at each sleeping body (World's bodies have their centre of mass at the origin).
    if (flags & DEBUGDRAW_Sleeping)
        for (const RecordedBody& b : f.bodies)
            if (b.asleep()) out.drawText(b.origin, kRecDrawSleepMark, debugcolour::kSleeping);
}
