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

// A grid in the plane under the rest of the scene (the scene's bounding box projected onto the plane, with
// a margin), kDrawPlaneCells cells each way; a short line along the normal at its centre shows the free
// side. With nothing else to see, a square around the point nearest the origin.
void spaceDrawPlane(iDebugDraw& out, const gcol::PlaneShape& p, const gcol::Aabb& scene, bool sceneBounded,
                    DebugColour colour) {
    const Vector n = p.normal;
    // Tangents: x projected into the plane unless the normal is close to x (then y).
    const Vector pick = std::fabs(n.x) < 0.9f ? Vector(1, 0, 0) : Vector(0, 1, 0);
    const Vector u = (pick - n * dot(pick, n)).normalize();
    const Vector v = cross(n, u);
    float lo[2] = {0, 0}, hi[2] = {0, 0}; // the scene's extent along u and v
    for (int i = 0; sceneBounded && i < 8; ++i) {
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
        half[k] = std::ceil(std::fmax(kDrawMinPlaneHalfSize, 0.5f * (hi[k] - lo[k]) + margin));
    }
    const Vector centre = u * mid[0] + v * mid[1] + n * p.offset; // u, v, n are orthonormal
    const float cellU = 2.0f * half[0] / float(kDrawPlaneCells),
                cellV = 2.0f * half[1] / float(kDrawPlaneCells);
    for (int i = 0; i <= kDrawPlaneCells; ++i) {
        const float a = -half[0] + cellU * float(i), b = -half[1] + cellV * float(i);
        out.drawLine(centre + u * a - v * half[1], centre + u * a + v * half[1], colour);
        out.drawLine(centre + v * b - u * half[0], centre + v * b + u * half[0], colour);
    }
    out.drawLine(centre, centre + n * std::fmin(cellU, cellV), colour);
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
    settle();
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
