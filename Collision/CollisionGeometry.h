// CollisionGeometry.h - the base every geometry of this package shares: body binding, space membership,
// the body-lifetime watch, and the conversion of the body's pose into world-space shapes.
//
// CollisionGeometry::setGlobalCollisionSpace is the seed's way to choose the space new geometries join.
// Spaces talk to a geometry through this class (worldShapes, the per-space bookkeeping); a geometry that
// does not derive from it cannot be added to this package's spaces. It is also the geometry's collision
// filter (layers, mask, sensor: iCollisionFilter.h).
#pragma once

#include "RBDynamics.h"
#include "Shapes.h"
#include "iCollisionFilter.h"
#include "iCollisionGeometry.h"
#include "iCollisionSpace.h"
#include "iUserPointer.h"

#include <cstdint>
#include <list>
#include <vector>

class iRigidBody;

// On a cache line of its own: what a space call reads of every geometry (the filter, the body, the space
// state's first fields: 56 bytes) is then one line.
class alignas(64) CollisionGeometry : public iCollisionFilter {
public:
    // Sets the space that geometries created from now on join (nullptr: none).
    static void setGlobalCollisionSpace(iCollisionSpace* cs) { setDefaultCollisionSpace(cs); }
    static iCollisionSpace* getGlobalCollisionSpace() { return getDefaultCollisionSpace(); }
    // The CollisionGeometry behind an interface pointer (nullptr if it is not one of this package's).
    static CollisionGeometry* from(iCollisionGeometry* g) { return dynamic_cast<CollisionGeometry*>(g); }

    // How many shapes it is made of (changes only with its shape version).
    virtual int shapeCount() const = 0;
    // Writes its shapeCount() shapes at the body pose (origin, row-vector rotation) to out[0..count).
    virtual void writeWorldShapes(const Vector& origin, const Matrix& rotation,
                                  gcol::WorldShape* out) const = 0;
    // Appends them to out.
    void worldShapes(const Vector& origin, const Matrix& rotation, std::vector<gcol::WorldShape>& out) const {
        const size_t n = out.size();
        out.resize(n + size_t(shapeCount()));
        writeWorldShapes(origin, rotation, out.data() + n);
    }
    // The smallest dimension (diameter or full box width) of its shapes: the scale for motion sampling.
    virtual float minDimension() const = 0;
    virtual iCollisionGeometry* asInterface() = 0;
    // True for a plane: infinite, and static when it has no body.
    virtual bool isPlane() const { return false; }
    // True when it is one shape at its body's origin, with its body's axes, whose writeWorldShapes is
    // gcol::placeAtBody: a space moves the shape it holds with the body without asking the geometry.
    virtual bool centredOnBody() const { return false; }
    // The solid this geometry is, for its body's inertia (RBDynamics::setShapeMass): volume 0 for none (a
    // plane, an empty compound).
    virtual ShapeMass shapeMass() const { return ShapeMass(); }

    // iCollisionFilter: plain values, read by the space at its next populateContactList.
    // (final: a space reads them for every geometry every call, without a virtual call.)
    void setLayer(std::uint32_t layerBits) final {
        m_layer = layerBits;
        edited();
    }
    std::uint32_t getLayer() const final { return m_layer; }
    void setMask(std::uint32_t maskBits) final {
        m_mask = maskBits;
        edited();
    }
    std::uint32_t getMask() const final { return m_mask; }
    void setSensor(bool sensor) final {
        m_sensor = sensor;
        edited();
    }
    bool isSensor() const final { return m_sensor; }
    // A clone filters as its original does.
    void copyFilter(const CollisionGeometry& from) {
        m_layer = from.m_layer;
        m_mask = from.m_mask;
        m_sensor = from.m_sensor;
        edited();
    }

    // The body pose this geometry is at now: false (pose left unset) when the body's dynamics are not
    // finite. A bodiless geometry is at the world origin.
    bool currentPose(Vector& origin, Matrix& rotation) const;

    // --- bookkeeping owned by the space the geometry is in ---
    struct SpaceState {
        bool hasPrevious = false;       // previous pose valid (continuous sampling)
        bool reportedBad = false;       // the non-finite pose has been reported once
        bool pendingDelete = false;     // Delete() called during listener notification
        bool pendingRemove = false;     // remove() called during listener notification
        unsigned previousTeleports = 0; // the body's (and its root's) RBDynamics::teleports then
        const iRigidBody* previousBody = nullptr;
        int entry = -1;               // its entry in the space (SimpleCollisionSpace::Entry), once laid out
        int proxy = -1;               // its broadphase proxy, if the space's broadphase keeps one
        unsigned long long order = 0; // when it joined the space (increasing along the space's list)
        std::list<iCollisionGeometry*>::iterator listed; // its place in the space's list (while a member)
        int member = -1;                                 // its place among the space's members
        Vector previousOrigin;
        Matrix previousRotation = Matrix(1);
    };
    SpaceState& spaceState() { return m_state; }
    const SpaceState& spaceState() const { return m_state; }
    void setSpace(iCollisionSpace* s) { m_space = s; }
    iCollisionSpace* space() const { return m_space; }
    iRigidBody* body() const { return m_body; }
    // Still bound to b and staying in its space: a listener or observer called before may have removed,
    // deleted or rebound it.
    bool stillBoundTo(const iRigidBody* b) const {
        return m_body == b && !m_state.pendingDelete && !m_state.pendingRemove;
    }
    // Changes whenever the geometry's shapes change (a radius, a child): a pose and this version tell its
    // bounds.
    unsigned shapeVersion() const { return m_shapeVersion; }
    // Binds to rb (nullptr: none). The geometry's solid moves from the old body's shape to rb's, so an
    // inertia the engine derives follows it (RBDynamics.h).
    void bind(iRigidBody* rb);
    // Its body is being destroyed (rigidBodyDestroyed): unbound without touching the body's dynamics.
    static void bodyDestroyed(CollisionGeometry& g);

protected:
    CollisionGeometry() = default;
    virtual ~CollisionGeometry();
    // Joins the default space (called by the factories once the object is complete). A factory passes its
    // name: with no default space the new geometry joins none, and that is reported with error().
    void joinDefaultSpace(const wchar_t* factory = nullptr);
    // Leaves the space (deferred if that space is busy notifying listeners) and deletes this.
    void destroy() const;
    // Tells the body the geometry's solid changed (a new radius, a child added).
    void shapeChanged();
    // Tells its space's entry that what the entry keeps of the geometry (filter, body, shape version, the
    // space state's previous pose) may have changed: the entry reads the geometry again at the next call
    // (a call otherwise reads of it only what its entry lacks: SpaceGather.cpp, gatherEntry).
    void edited();

private:
    friend class SimpleCollisionSpace; // deletes geometry whose Delete() it deferred
    // (What a space reads every call first, beside the space state's flags.)
    iRigidBody* m_body = nullptr;
    unsigned m_shapeVersion = 0;
    std::uint32_t m_layer = 1, m_mask = ~std::uint32_t(0);
    bool m_sensor = false;
    SpaceState m_state;
    iCollisionSpace* m_space = nullptr;
};

// Implements the iCollisionGeometry functions every concrete geometry shares.
template <class Interface>
class GeometryImpl : public Interface, public CollisionGeometry, public iUserPointer {
public:
    void attach(iRigidBody* rb) override { bind(rb); }
    iRigidBody* getRigidBody() override { return body(); }
    const iRigidBody* getRigidBody() const override { return body(); }
    iCollisionSpace* getSpace() const override { return space(); }
    void getProjectionBounds(const Vector& axis, float& min, float& max) const override {
        Vector o;
        Matrix r(1);
        min = max = 0.0f;
        if (!currentPose(o, r)) return;
        std::vector<gcol::WorldShape> shapes;
        worldShapes(o, r, shapes);
        Vector unit = axis.normalize();
        for (size_t i = 0; i < shapes.size(); ++i) {
            float lo, hi;
            gcol::shapeProjection(shapes[i], unit, lo, hi);
            min = i == 0 ? lo : std::fmin(min, lo);
            max = i == 0 ? hi : std::fmax(max, hi);
        }
    }
    iCollisionGeometry* asInterface() override { return this; }
    // Nothing to suspend or release: a geometry holds no device resources.
    void suspend() const override {}
    void release() const override {}
    void Delete() const override { destroy(); }
    // --- iUserPointer ---
    void setUserPointer(void* p) override { m_userPointer = p; }
    void* getUserPointer() const override { return m_userPointer; }

private:
    void* m_userPointer = nullptr;
};
