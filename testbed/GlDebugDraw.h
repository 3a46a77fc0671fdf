// GlDebugDraw.h - the testbed's iDebugDraw: what the engine draws (iDebugDrawable), collected for a frame
// and drawn with OpenGL 1.1 vertex arrays (the fixed-function pipeline: no shaders, no loader).
//
// Shapes are drawn solid so that a scene reads at a glance: a wire box or wire sphere becomes a flat-shaded
// solid in its colour with darker edges (bounding boxes, drawn in debugcolour::kBounds, stay wire). Lines and
// points are drawn as they come. Text is only collected: the window writes it over the picture (ImGui).
#pragma once

#include "iDebugDraw.h"

#include <cstdint>
#include <string>
#include <vector>

class GlDebugDraw final : public iDebugDraw {
public:
    struct Text {
        Vector at;
        std::string text;
        DebugColour colour;
    };

    GlDebugDraw();

    void drawLine(const Vector& from, const Vector& to, DebugColour colour) override;
    void drawText(const Vector& at, const char* text, DebugColour colour) override;
    void drawPoint(const Vector& at, float size, DebugColour colour) override;
    void drawWireSphere(const Vector& centre, float radius, DebugColour colour) override;
    void drawWireBox(const Vector& centre, const Vector& halfExtents, const Matrix& orientation,
                     DebugColour colour) override;

    // Forgets the last frame's drawing.
    void clear();
    // Draws what was collected with viewProjection (a row-vector matrix with OpenGL's depth range:
    // OrbitCamera::glViewProjection) into the current OpenGL context. Leaves depth testing off.
    void render(const Matrix& viewProjection) const;

    const std::vector<Text>& texts() const { return m_texts; }
    size_t triangleCount() const { return m_triangles.size() / 3; }
    size_t lineCount() const { return m_lines.size() / 2; }

private:
    struct Vertex {
        float x, y, z;
        std::uint8_t rgba[4];
    };
    static Vertex vertex(const Vector& p, DebugColour colour, float shade = 1.0f);
    void triangle(const Vector& a, const Vector& b, const Vector& c, DebugColour colour, float shade);

    std::vector<Vertex> m_lines, m_triangles, m_points;
    std::vector<Text> m_texts;
    std::vector<Vector> m_unitSphere; // triangles of a unit sphere, three vertices each
};
