// iDebugDraw.h - what the engine draws with when asked to show itself (iDebugDrawable.h): the GAME
// implements it with its own renderer, the engine only calls it.
//
// A game implements two functions, drawLine and drawText; points, wire spheres and wire boxes have
// defaults made of lines (the non-virtual helpers below), which a renderer with better primitives may
// override. Everything is in world space (metres, y up, row-vector matrices: README "Conventions").
// Colours are packed 0xAARRGGBB, as the course framework's COLOUR_TO_ARGB and Direct3D's D3DCOLOR.
#pragma once

#include "MathDeclarations.h"

#include <cstdint>

using DebugColour = std::uint32_t; // 0xAARRGGBB

// The colours the engine uses for each part (a game that wants others can map them in its drawLine).
namespace debugcolour {
constexpr DebugColour kShape = 0xFF30C030u;    // geometry of awake bodies: green
constexpr DebugColour kSleeping = 0xFF6080FFu; // geometry of sleeping bodies: blue
constexpr DebugColour kFixed = 0xFF909090u;    // geometry of fixed bodies and bodiless planes: grey
constexpr DebugColour kBounds = 0xFFE0C000u;   // bounding boxes: yellow
constexpr DebugColour kContact = 0xFFFF2020u;  // contact points and normals: red
constexpr DebugColour kIsland = 0xFFFF40FFu;   // island links: magenta
constexpr DebugColour kAxisX = 0xFFFF0000u;    // body axes: x red, y green, z blue
constexpr DebugColour kAxisY = 0xFF00FF00u;
constexpr DebugColour kAxisZ = 0xFF0000FFu;
} // namespace debugcolour

// What to draw: or them together. Each part is switched on and off alone.
enum DebugDrawFlag : unsigned {
    DEBUGDRAW_Shapes = 1u << 0,         // spheres, boxes, planes (a finite grid patch), compound children
    DEBUGDRAW_Bounds = 1u << 1,         // each geometry's world bounding box
    DEBUGDRAW_ContactPoints = 1u << 2,  // the space's current contact list: a point per contact
    DEBUGDRAW_ContactNormals = 1u << 3, // ... and its normal, a short line from the point (towards g2)
    DEBUGDRAW_Sleeping = 1u << 4,       // sleeping bodies: their shapes in kSleeping, "zz" at their centre
    DEBUGDRAW_Islands = 1u << 5,        // a line from each body to the first body of its island of contacts
    DEBUGDRAW_BodyAxes = 1u << 6, // each body's centre of mass and its local axes (x red, y green, z blue)
    DEBUGDRAW_Default =
        DEBUGDRAW_Shapes | DEBUGDRAW_ContactPoints | DEBUGDRAW_ContactNormals | DEBUGDRAW_Sleeping,
    DEBUGDRAW_All = (1u << 7) - 1u
};

class iDebugDraw {
public:
    // The two a game must implement.
    virtual void drawLine(const Vector& from, const Vector& to, DebugColour colour) = 0;
    virtual void drawText(const Vector& at, const char* text, DebugColour colour) = 0;

    // A point of the given size (m): by default a small three-line cross.
    virtual void drawPoint(const Vector& at, float size, DebugColour colour) {
        drawPointAsLines(at, size, colour);
    }
    // By default three great circles (in the world's xy, yz and zx planes) of kCircleSegments lines each.
    virtual void drawWireSphere(const Vector& centre, float radius, DebugColour colour) {
        drawSphereAsLines(centre, radius, colour);
    }
    // orientation: row-vector rotation, box local -> world. By default the 12 edges.
    virtual void drawWireBox(const Vector& centre, const Vector& halfExtents, const Matrix& orientation,
                             DebugColour colour) {
        drawBoxAsLines(centre, halfExtents, orientation, colour);
    }

    static constexpr int kCircleSegments = 24;

    // The defaults, kept non-virtual so that an override can still fall back on them.
    void drawPointAsLines(const Vector& at, float size, DebugColour colour) {
        const float h = size * 0.5f;
        drawLine(at - Vector(h, 0, 0), at + Vector(h, 0, 0), colour);
        drawLine(at - Vector(0, h, 0), at + Vector(0, h, 0), colour);
        drawLine(at - Vector(0, 0, h), at + Vector(0, 0, h), colour);
    }
    // A circle of radius r around centre in the plane spanned by the unit vectors u and v.
    void drawCircleAsLines(const Vector& centre, const Vector& u, const Vector& v, float r,
                           DebugColour colour) {
        const float step = float(2.0 * M_PI / kCircleSegments);
        Vector previous = centre + u * r;
        for (int i = 1; i <= kCircleSegments; ++i) {
            const float a = step * float(i);
            Vector next = centre + u * (r * std::cos(a)) + v * (r * std::sin(a));
            drawLine(previous, next, colour);
            previous = next;
        }
    }
    void drawSphereAsLines(const Vector& centre, float radius, DebugColour colour) {
        const Vector x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
        drawCircleAsLines(centre, x, y, radius, colour);
        drawCircleAsLines(centre, y, z, radius, colour);
        drawCircleAsLines(centre, z, x, radius, colour);
    }
    void drawBoxAsLines(const Vector& centre, const Vector& halfExtents, const Matrix& orientation,
                        DebugColour colour) {
        // Corner i has the sign of bit 0, 1, 2 along local x, y, z; an edge joins corners one bit apart.
        Vector corner[8];
        for (int i = 0; i < 8; ++i) {
            Vector local(i & 1 ? halfExtents.x : -halfExtents.x, i & 2 ? halfExtents.y : -halfExtents.y,
                         i & 4 ? halfExtents.z : -halfExtents.z);
            corner[i] = centre + orientation.direction(local);
        }
        for (int i = 0; i < 8; ++i)
            for (int bit = 1; bit < 8; bit <<= 1)
                if (!(i & bit)) drawLine(corner[i], corner[i | bit], colour);
    }

protected:
    ~iDebugDraw() = default; // the game's object: the engine never deletes it
};
