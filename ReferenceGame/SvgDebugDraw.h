// SvgDebugDraw.h - an iDebugDraw that makes a picture without a window: it collects what the engine draws
// and writes it as an SVG file (plain text, no dependency), seen through a fixed orthographic camera.
//
// The camera looks along a stated direction (default: from the front, above and to the left) with world y
// up on the page; the picture is fitted to everything drawn, keeping proportions. Shapes are painted far to
// near, so nearer lines cover farther ones. Used by ReferenceGame --image and by the tests.
#pragma once

#include "iDebugDraw.h"

#include <string>
#include <vector>

class SvgDebugDraw final : public iDebugDraw {
public:
    struct Pixel {
        float x, y; // from the picture's top left corner, y down (SVG's axes)
    };

    // viewDirection: where the camera looks (need not be unit; non-zero). margin: empty pixels at each side.
    explicit SvgDebugDraw(int width = 800, int height = 600, const Vector& viewDirection = Vector(1, -1, 2),
                          float margin = 10.0f);

    void drawLine(const Vector& from, const Vector& to, DebugColour colour) override;
    void drawText(const Vector& at, const char* text, DebugColour colour) override;
    void drawPoint(const Vector& at, float size, DebugColour colour) override; // a dot
    // An orthographic camera sees a sphere as a circle: one outline instead of three great circles.
    void drawWireSphere(const Vector& centre, float radius, DebugColour colour) override;

    // Forgets what was drawn (to draw the next frame into the same object).
    void clear();
    // How many lines, dots, circles and texts are collected.
    size_t shapeCount() const { return m_items.size(); }
    // Where a world point lands in the picture fitted to what is collected now.
    Pixel project(const Vector& p) const;
    // The picture as SVG text: "<svg ...>" ... "</svg>\n".
    std::string svg() const;
    // Writes svg() to path; false (and nothing written) when the file cannot be opened.
    bool write(const std::string& path) const;

private:
    struct Item {
        enum Kind { Line, Dot, Circle, Text } kind;
        Vector a, b; // Line: from, to; Dot, Circle, Text: a is the place
        float size;  // Dot, Circle: radius in metres
        DebugColour colour;
        std::string text; // Text only
    };
    // The camera's screen coordinates of a world point (right, up), before fitting, and its depth.
    float right(const Vector& p) const { return dot(p, m_right); }
    float up(const Vector& p) const { return dot(p, m_up); }
    float depth(const Item& item) const;
    // The fit: a world-screen rectangle mapped into the picture (computed from the items).
    struct Fit {
        float minRight, minUp, scale, offsetX, offsetY;
    };
    Fit fit() const;
    Pixel toPixel(const Fit& f, const Vector& p) const;

    int m_width, m_height;
    float m_margin;
    Vector m_forward, m_right, m_up;
    std::vector<Item> m_items;
};
