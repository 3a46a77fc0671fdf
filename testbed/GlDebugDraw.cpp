// GlDebugDraw.cpp - collecting the engine's debug drawing and drawing it with OpenGL (GlDebugDraw.h).
#include "GlDebugDraw.h"

#include "MathDefinitions.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

namespace {

const int kSlices = 16, kStacks = 10; // the solid sphere's tessellation
const float kEdgeShade = 0.45f;       // edges of solid shapes: this much of the shape's colour

// Flat shading from one fixed light above, to the right of and in front of the default view.
float shadeOf(const Vector& n) {
    const Vector light = normal(Vector(0.4f, 1.0f, -0.6f));
    return 0.55f + 0.45f * std::max(0.0f, dot(n, light));
}

// The colour with its red, green and blue scaled by f (0..1), alpha kept.
DebugColour scaled(DebugColour c, float f) {
    auto channel = [&](int shift) { return DebugColour(float((c >> shift) & 0xFFu) * f + 0.5f) << shift; };
    return (c & 0xFF000000u) | channel(16) | channel(8) | channel(0);
}

} // namespace

GlDebugDraw::GlDebugDraw() {
    auto at = [](int stack, int slice) {
        const float theta = float(M_PI) * float(stack) / kStacks, phi = 2.0f * float(M_PI) * slice / kSlices;
        return Vector(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    for (int i = 0; i < kStacks; ++i)
        for (int j = 0; j < kSlices; ++j) {
            const Vector a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            m_unitSphere.insert(m_unitSphere.end(), {a, b, c, a, c, d});
        }
}

GlDebugDraw::Vertex GlDebugDraw::vertex(const Vector& p, DebugColour colour, float shade) {
    auto channel = [&](int shift) {
        return std::uint8_t(std::min(255.0f, float((colour >> shift) & 0xFFu) * shade + 0.5f));
    };
    return Vertex{p.x, p.y, p.z, {channel(16), channel(8), channel(0), std::uint8_t(colour >> 24)}};
}

void GlDebugDraw::triangle(const Vector& a, const Vector& b, const Vector& c, DebugColour colour,
                           float shade) {
    m_triangles.push_back(vertex(a, colour, shade));
    m_triangles.push_back(vertex(b, colour, shade));
    m_triangles.push_back(vertex(c, colour, shade));
}

void GlDebugDraw::drawLine(const Vector& from, const Vector& to, DebugColour colour) {
    m_lines.push_back(vertex(from, colour));
    m_lines.push_back(vertex(to, colour));
}

void GlDebugDraw::drawText(const Vector& at, const char* text, DebugColour colour) {
    m_texts.push_back(Text{at, text ? text : "", colour});
}

void GlDebugDraw::drawPoint(const Vector& at, float, DebugColour colour) {
    m_points.push_back(vertex(at, colour)); // a fixed-size dot: readable at any distance
}

void GlDebugDraw::drawWireSphere(const Vector& centre, float radius, DebugColour colour) {
    for (size_t i = 0; i < m_unitSphere.size(); i += 3) {
        const Vector& a = m_unitSphere[i];
        const Vector& b = m_unitSphere[i + 1];
        const Vector& c = m_unitSphere[i + 2];
        const Vector n = normal(a + b + c);
        triangle(centre + a * radius, centre + b * radius, centre + c * radius, colour, shadeOf(n));
    }
}

void GlDebugDraw::drawWireBox(const Vector& centre, const Vector& halfExtents, const Matrix& orientation,
                              DebugColour colour) {
    if (colour != debugcolour::kBounds) {
        // Corner i has the sign of bit 0, 1, 2 along local x, y, z (as iDebugDraw::drawBoxAsLines).
        Vector corner[8];
        for (int i = 0; i < 8; ++i) {
            const Vector local(i & 1 ? halfExtents.x : -halfExtents.x, i & 2 ? halfExtents.y : -halfExtents.y,
                               i & 4 ? halfExtents.z : -halfExtents.z);
            corner[i] = centre + orientation.direction(local);
        }
        for (int axis = 0; axis < 3; ++axis) {
            const int bit = 1 << axis, u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3);
            for (int side = 0; side < 2; ++side) {
                const int base = side ? bit : 0;
                const Vector localNormal(axis == 0 ? (side ? 1.f : -1.f) : 0.f,
                                         axis == 1 ? (side ? 1.f : -1.f) : 0.f,
                                         axis == 2 ? (side ? 1.f : -1.f) : 0.f);
                const float shade = shadeOf(orientation.direction(localNormal));
                triangle(corner[base], corner[base | u], corner[base | u | v], colour, shade);
                triangle(corner[base], corner[base | u | v], corner[base | v], colour, shade);
            }
        }
        drawBoxAsLines(centre, halfExtents, orientation, scaled(colour, kEdgeShade));
        return;
    }
    drawBoxAsLines(centre, halfExtents, orientation, colour);
}

void GlDebugDraw::clear() {
    m_lines.clear();
    m_triangles.clear();
    m_points.clear();
    m_texts.clear();
}

void GlDebugDraw::render(const Matrix& viewProjection) const {
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(viewProjection.data());
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    auto draw = [](const std::vector<Vertex>& v, GLenum mode) {
        if (v.empty()) return;
        glVertexPointer(3, GL_FLOAT, sizeof(Vertex), &v[0].x);
        glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), v[0].rgba);
        glDrawArrays(mode, 0, GLsizei(v.size()));
    };
    // Solids a little behind their edges, so that the edges win the depth test.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    draw(m_triangles, GL_TRIANGLES);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glLineWidth(1.0f);
    draw(m_lines, GL_LINES);
    glPointSize(5.0f);
    draw(m_points, GL_POINTS);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_DEPTH_TEST);
}
