// SpaceDebugDraw.cpp - the space drawing itself through a game's iDebugDraw (iDebugDrawable.h): every
// geometry's shapes at its body's current pose (a plane as a finite grid patch under the rest), their
// bounding boxes, and the contact list of the last populateContactList call.
//
// Drawing only reads: it allocates its own scratch rather than touch the populate call's.
#include "SimpleCollisionSpace.h"
#include "iRigidBody.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

constexpr float kDrawContactPointSize = 0.1f;    // m: the cross drawn at a contact point
constexpr float kDrawContactNormalLength = 0.5f; // m: the line drawn along a contact normal
constexpr int kDrawPlaneCells = 10;           // a plane's patch is kDrawPlaneCells x kDrawPlaneCells squares
constexpr float kDrawMinPlaneHalfSize = 2.0f; // m: the patch's half size when there is little else to see

// The colour of a geometry's shapes: fixed (or bodiless) grey, sleeping blue when asked, else green.
DebugColour spaceDrawColour(const iRigidBody* body, unsigned flags) {
    if (!body) return debugcolour::kFixed;
    const RBDynamics& root = *body->getDynamics().attachmentRoot();
    if (root.physicsType == PHYS_FixedInSpace) return debugcolour::kFixed;
    if ((flags & DEBUGDRAW_Sleeping) && root.sleeping) return debugcolour::kSleeping;
    return debugcolour::kShape;
}

// A box's rotation (row i = its local axis i in world space), as iDebugDraw::drawWireBox takes it.
Matrix spaceDrawBoxRotation(const gcol::BoxShape& b) {
    return Matrix(b.axis[0].x, b.axis[0].y, b.axis[0].z, 0, b.axis[1].x, b.axis[1].y, b.axis[1].z, 0,
                  b.axis[2].x, b.axis[2].y, b.axis[2].z, 0, 0, 0, 0, 1);
}

// A square grid in the plane, centred where the plane is closest to the middle of the rest of the scene
// and large enough to lie under all of it; a short line along the normal shows the free side.
void spaceDrawPlane(iDebugDraw& out, const gcol::PlaneShape& p, const gcol::Aabb& scene, bool sceneBounded,
                    DebugColour colour) {
    const Vector n = p.normal;
    Vector middle, span;
    if (sceneBounded) {
        middle = (scene.min + scene.max) * 0.5f;
        span = scene.max - scene.min;
    }
    const Vector centre = middle + n * (p.offset - dot(n, middle));
    const float half = std::ceil(std::fmax(kDrawMinPlaneHalfSize, 0.55f * span.length()));
    // Tangents: x projected into the plane unless the normal is close to x (then y).
    const Vector pick = std::fabs(n.x) < 0.9f ? Vector(1, 0, 0) : Vector(0, 1, 0);
    const Vector u = (pick - n * dot(pick, n)).normalize();
    const Vector v = cross(n, u);
    const float cell = 2.0f * half / float(kDrawPlaneCells);
    for (int i = 0; i <= kDrawPlaneCells; ++i) {
        const float t = -half + cell * float(i);
        out.drawLine(centre + u * t - v * half, centre + u * t + v * half, colour);
        out.drawLine(centre + v * t - u * half, centre + v * t + u * half, colour);
    }
    out.drawLine(centre, centre + n * cell, colour);
}

// Grows bounds (empty while bounded is false) to hold box.
void spaceDrawGrow(gcol::Aabb& bounds, bool& bounded, const gcol::Aabb& box) {
    if (!bounded) {
        bounds = box;
        bounded = true;
        return;
    }
    bounds.min = Vector(std::fmin(bounds.min.x, box.min.x), std::fmin(bounds.min.y, box.min.y),
                        std::fmin(bounds.min.z, box.min.z));
    bounds.max = Vector(std::fmax(bounds.max.x, box.max.x), std::fmax(bounds.max.y, box.max.y),
                        std::fmax(bounds.max.z, box.max.z));
}

void spaceDrawShape(iDebugDraw& out, const gcol::WorldShape& s, DebugColour colour) {
    if (s.kind == gcol::ShapeKind::Sphere)
        out.drawWireSphere(s.sphere.centre, s.sphere.radius, colour);
    else if (s.kind == gcol::ShapeKind::Box)
        out.drawWireBox(s.box.centre, s.box.halfExtents, spaceDrawBoxRotation(s.box), colour);
}

} // namespace

void SimpleCollisionSpace::debugDraw(iDebugDraw& out, unsigned flags) const {
    // Every drawable geometry's shapes at its current pose, as the queries see them; planes wait until the
    // bounds of everything else are known.
    struct Drawn {
        gcol::WorldShape shape;
        DebugColour colour;
        int geometry; // which geometry (its shapes are consecutive)
    };
    std::vector<Drawn> drawn;
    std::vector<gcol::WorldShape> shapes;
    gcol::Aabb scene;
    bool sceneBounded = false;
    for (size_t i = 0; i < m_members.size(); ++i) {
        const CollisionGeometry* g = m_members[i];
        const CollisionGeometry::SpaceState& st = g->spaceState();
        if (st.pendingDelete || st.pendingRemove || (!g->body() && !g->isPlane())) continue;
        Vector origin;
        Matrix rotation(1);
        if (!g->currentPose(origin, rotation)) continue;
        shapes.clear();
        g->worldShapes(origin, rotation, shapes);
        const DebugColour colour = spaceDrawColour(g->body(), flags);
        for (const gcol::WorldShape& s : shapes) {
            drawn.push_back({s, colour, int(i)});
            gcol::Aabb box;
            if (gcol::shapeAabb(s, box)) spaceDrawGrow(scene, sceneBounded, box);
        }
    }

    if (flags & DEBUGDRAW_Shapes) {
        for (const Drawn& d : drawn) {
            if (d.shape.kind == gcol::ShapeKind::Plane)
                spaceDrawPlane(out, d.shape.plane, scene, sceneBounded, d.colour);
            else
                spaceDrawShape(out, d.shape, d.colour);
        }
    }

    if (flags & DEBUGDRAW_Bounds) { // one box per geometry: the union of its shapes' (planes have none)
        for (size_t i = 0; i < drawn.size();) {
            gcol::Aabb all, box;
            bool bounded = false;
            size_t j = i;
            for (; j < drawn.size() && drawn[j].geometry == drawn[i].geometry; ++j) {
                if (gcol::shapeAabb(drawn[j].shape, box)) spaceDrawGrow(all, bounded, box);
            }
            if (bounded)
                out.drawWireBox((all.min + all.max) * 0.5f, (all.max - all.min) * 0.5f, Matrix(1),
                                debugcolour::kBounds);
            i = j;
        }
    }

    for (const CollisionContact& c : m_contacts) {
        if (flags & DEBUGDRAW_ContactPoints)
            out.drawPoint(c.pos, kDrawContactPointSize, debugcolour::kContact);
        if (flags & DEBUGDRAW_ContactNormals)
            out.drawLine(c.pos, c.pos + c.normal * kDrawContactNormalLength, debugcolour::kContact);
    }
}
