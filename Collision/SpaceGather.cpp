// SpaceGather.cpp - step 1 of a space's call (SimpleCollisionSpace.h): every member's entry brought up to
// date with its geometry and body. An entry keeps its world shapes and box while its body's pose, its shape
// version and its body are as at the last call, so a call where little moved reads little; while no edit
// reached a geometry its entry stands for it, and the geometry itself is not read; one that moved is built
// without a load waiting on a store (VectorRegister.h) and with the cache lines it needs asked for a few
// entries ahead.
#include "BoxAxes.h"
#include "FetchAhead.h"
#include "MathEigen.h"
#include "PoseInputs.h"
#include "SimpleCollisionSpace.h"
#include "VectorRegister.h"
#include "iRigidBody.h"
#include "iUtilities.h"

#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace {

// Angle of the rotation taking a to b (both row-vector rotations).
float rotationAngle(const Matrix& a, const Matrix& b) {
    gmath::Mat3 rel = gmath::block3(a).transpose() * gmath::block3(b);
    float c = 0.5f * (rel.trace() - 1.0f);
    return std::acos(std::fmax(-1.0f, std::fmin(1.0f, c)));
}

void grow(gcol::Aabb& box, const gcol::Aabb& other) {
    box.min = Vector(std::fmin(box.min.x, other.min.x), std::fmin(box.min.y, other.min.y),
                     std::fmin(box.min.z, other.min.z));
    box.max = Vector(std::fmax(box.max.x, other.max.x), std::fmax(box.max.y, other.max.y),
                     std::fmax(box.max.z, other.max.z));
}

} // namespace

namespace {

using gcol::sameWords;
bool sameBits(const Vector& a, const Vector& b) { return sameWords<3>(&a, &b); }
bool sameBits(const Matrix& a, const Matrix& b) { return sameWords<16>(&a, &b); }
// Boxes are compared and copied a Vector at a time through registers (VectorRegister.h): the one compared is
// usually just written.
bool sameBits(const gcol::Aabb& a, const gcol::Aabb& b) {
#if defined(__SSE2__)
    return gcol::sameBits3(gcol::load3(a.min), gcol::load3(b.min)) &&
           gcol::sameBits3(gcol::load3(a.max), gcol::load3(b.max));
#else
    return sameWords<6>(&a, &b);
#endif
}
void copyBox(gcol::Aabb& to, const gcol::Aabb& from) {
#if defined(__SSE2__)
    gcol::store3(to.min, gcol::load3(from.min));
    gcol::store3(to.max, gcol::load3(from.max));
#else
    to = from;
#endif
}
// A box kept to compare with after it may have been rewritten (in registers on SSE2).
class HeldBox {
public:
#if defined(__SSE2__)
    explicit HeldBox(const gcol::Aabb& b) : m_min(gcol::load3(b.min)), m_max(gcol::load3(b.max)) {}
    bool sameAs(const gcol::Aabb& b) const {
        return gcol::sameBits3(m_min, gcol::load3(b.min)) && gcol::sameBits3(m_max, gcol::load3(b.max));
    }

private:
    __m128 m_min, m_max;
#else
    explicit HeldBox(const gcol::Aabb& b) : m_box(b) {}
    bool sameAs(const gcol::Aabb& b) const { return sameBits(m_box, b); }

private:
    gcol::Aabb m_box;
#endif
};

// gcol::shapeAabb of a bounded shape, the box's case written out (BoxAxes.h).
inline void shapeBounds(const gcol::WorldShape& s, gcol::Aabb& out) {
    if (s.kind == gcol::ShapeKind::Box)
        gcol::boxBounds(s.box, out);
    else
        gcol::shapeAabb(s, out);
}

// CollisionGeometry::currentPose of a geometry on d, a body without a parent: the same operations on the
// same inputs (RBDynamics::getWorldOrigin, getWorldOrientation), without the copies. On SSE2 the rotation's
// rows go from the orientation to rotation in registers (built on the stack a float at a time and read back
// sixteen bytes at a time, they stalled the load: a third of gathering a moved box, perf), and o.isFinite()
// && r.isFinite() is one test: x - x is 0 for a finite x and NaN for an infinite or NaN one, and a sum of
// those is 0 only when every one is.
bool rawPose(const RBDynamics& d, Vector& origin, Matrix& rotation) {
    const Vector o = d.position - d.orientation.direction(d.com);
#if defined(__SSE2__)
    const float* m = d.orientation.data();
    const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1)); // (the fourth column is 0: +0 bits)
    const __m128 x = _mm_and_ps(xyz, _mm_loadu_ps(m)), y = _mm_and_ps(xyz, _mm_loadu_ps(m + 4)),
                 z = _mm_and_ps(xyz, _mm_loadu_ps(m + 8));
    const __m128 p = _mm_set_ps(0.0f, o.z, o.y, o.x);
    const __m128 sum = _mm_add_ps(_mm_add_ps(_mm_sub_ps(x, x), _mm_sub_ps(y, y)),
                                  _mm_add_ps(_mm_sub_ps(z, z), _mm_sub_ps(p, p)));
    if (_mm_movemask_ps(_mm_cmpeq_ps(sum, _mm_setzero_ps())) != 0xF) return false;
    float* r = rotation.data();
    _mm_storeu_ps(r, x);
    _mm_storeu_ps(r + 4, y);
    _mm_storeu_ps(r + 8, z);
    _mm_storeu_ps(r + 12, _mm_set_ps(1.0f, 0.0f, 0.0f, 0.0f));
#else
    const Matrix r = d.orientation.rotation();
    if (!o.isFinite() || !r.isFinite()) return false;
    rotation = r;
#endif
    origin = o;
    return true;
}

} // namespace

bool SimpleCollisionSpace::atEntryPose(const Entry& e, const CollisionGeometry& g) {
    const Entry::Cache& c = e.cache;
    if (e.g != &g || !e.active || !c.valid || !c.raw || !e.body || e.body != g.body() ||
        c.shapeVersion != g.shapeVersion())
        return false;
    const RBDynamics& d = e.body->getDynamics();
    return !d.attachedTo() && c.rawInputs.same(d);
}

// Brings e up to date with its geometry: false when the geometry takes no part in this call. A geometry
// whose body pose (origin, rotation), shape version and body are as at the last call keeps its shapes, box,
// sizes and bounding radius; the rest (filter, resting, teleports, the previous pose and motion) is worked
// out every call.
//
// What the call needs of the geometry itself (its filter, body, shape version, and the space state this
// space keeps in it) the entry mirrors while no edit reached the geometry since the last call
// (Cache::mirrored, CollisionGeometry::edited): then the geometry is not read, a cache line or three apart
// from everything else, unless the entry lacks something (its shapes at a new pose, when they do not simply
// sit at the body's origin; a previous pose the entry no longer holds). The candidate stage of 10,000 boxes,
// cache cold, mirrors on and off in alternate calls of one process: 0.87-0.89x the time where nothing moved,
// 0.76-0.89x where every box moved.
bool SimpleCollisionSpace::gatherEntry(Entry& e, bool continuous) {
    CollisionGeometry* g = e.g;
    Entry::Cache& c = e.cache;
    const bool mirrored = m_mirrors && c.mirrored && e.active && !e.plane && c.valid && e.body;
    iRigidBody* body = mirrored ? e.body : g->body();
    // A new filter may let something asleep on it through (disturbed, below).
    bool refiltered = false;
    if (!mirrored) {
        refiltered = e.layer != g->getLayer() || e.mask != g->getMask() || e.sensor != g->isSensor();
        e.layer = g->getLayer();
        e.mask = g->getMask();
        e.sensor = g->isSensor();
    }
    if (!body && !e.plane) {
        g->spaceState().hasPrevious = false;
        c.prevIsPose = c.mirrored = false;
        return false;
    }
    // Its body's dynamics, as found at the last call while the geometry has kept that body since (binding it
    // again changes the shape version): then the body itself is not read, a cache line a geometry
    // (iRigidBody.h: getDynamics() names the same RBDynamics for the body's lifetime).
    const unsigned version = mirrored ? c.shapeVersion : g->shapeVersion();
    const RBDynamics* d = !body                                                       ? nullptr
                          : body == e.body && c.dynamics && c.shapeVersion == version ? c.dynamics
                                                                                      : &body->getDynamics();
    const bool rootKnown = m_linksUnchanged && c.rootIsSelf && c.dynamics == d;
    c.dynamics = d;
    // Its root: itself when it had no parent at the last call and no attachment changed since (known without
    // reading the links).
    const RBDynamics* root = d && !rootKnown ? d->attachmentRoot() : d;
    c.rootIsSelf = d && root == d;
    // The space state this space keeps in the geometry (its previous body and teleports), as mirrored or
    // read.
    CollisionGeometry::SpaceState* st = mirrored ? nullptr : &g->spaceState();
    const bool hadPrevious = st ? st->hasPrevious : c.hadPrevious;
    const bool previousIsBody = st ? st->previousBody == body : c.previousIsBody;
    const unsigned previousTeleports = st ? st->previousTeleports : c.previousTeleports;
    const bool tracked = hadPrevious && previousIsBody; // it has a previous pose, of this body
    // The space state's previous pose is the entry's pose as the last call left it (prevIsPose): where it
    // is needed below and the pose changes now, the entry keeps it (in prevOrigin, prevRotation with
    // sampling), so the geometry need not be read for it.
    const bool previousInEntry = mirrored && c.prevIsPose && tracked;
    bool movedFromPrevious = false, previousKept = false;
    bool same = c.valid && e.body == body && c.shapeVersion == version; // never for a plane
    c.reposed = !same;
    if (!(same && c.raw && root == d && c.rawInputs.same(*d))) {
        Vector origin;
        Matrix rotation(1);
        if (!(d && root == d ? rawPose(*d, origin, rotation) : g->currentPose(origin, rotation))) {
            CollisionGeometry::SpaceState& state = g->spaceState();
            if (!state.reportedBad)
                error(
                    L"SimpleCollisionSpace: a body's position or orientation is not finite; its geometry is "
                    L"skipped until it is");
            state.reportedBad = true;
            state.hasPrevious = false;
            c.valid = c.prevIsPose = c.mirrored = false;
            return false;
        }
        same = same && sameBits(origin, e.origin) && sameBits(rotation, e.rotation);
        c.reposed = !same;
        if (previousInEntry && !same) {
            movedFromPrevious = e.origin != origin || e.rotation != rotation;
            if (continuous) {
                if (!c.prevIsSelf) {
                    e.prevOrigin = e.origin;
                    e.prevRotation = e.rotation;
                }
                previousKept = true;
            }
        }
        e.origin = origin;
        e.rotation = rotation;
        c.raw = d && root == d;
        if (c.raw) c.rawInputs.store(*d);
    }
    if (st) {
        st->reportedBad = false;
        c.mirrored = true;
        c.hadPrevious = hadPrevious;
        c.previousIsBody = previousIsBody;
        c.previousTeleports = previousTeleports;
    }
    e.body = body;
    e.teleports = root ? root->teleports + (root != d ? d->teleports : 0) : 0;
    // The pose of the previous call, unless the body is new here or was teleported since (never swept).
    const bool samePath = tracked && previousTeleports == e.teleports;
    // Resting bodies (fixed in space, or asleep) that did not move: a pair of two of them needs no test. One
    // the game moved (a platform, a lift) is tested, so it can push and wake what rests on it.
    const bool resting = !root || root->physicsType == PHYS_FixedInSpace || root->sleeping;
    if (!same) c.prevIsPose = false;
    // The previous pose is this pose, bit for bit (known without comparing).
    const bool prevIsPose = c.prevIsPose && tracked;
    const CollisionGeometry::SpaceState& state = st ? *st : g->spaceState(); // (read only where needed)
    const bool movedSinceLastCall =
        tracked && !prevIsPose &&
        (previousInEntry ? movedFromPrevious
                         : state.previousOrigin != e.origin || state.previousRotation != e.rotation);
    e.fixed = resting && !movedSinceLastCall;
    e.newcomer = !tracked;
    e.asleep = root && root->sleeping;
    if (e.newcomer && e.fixed) m_restingNewcomer = true;
    // What changed under a sleeping body touching it wakes that body (SpaceWake.cpp). A sleeping body has
    // not moved since it fell asleep (an edit wakes it; what moved it last was its last step), but its
    // shape may have changed; a body the simulator moves touches nothing asleep (its island woke): only what
    // rests without sleeping (fixed, kinematic, bodiless, a game's own), what is reshaped and what is taken
    // away ask for the walk.
    e.disturbed = !previousIsBody || c.shapeVersion != version || refiltered ||
                  (movedSinceLastCall && !(root && root->sleeping));
    const bool mover =
        root && !root->sleeping && root->physicsType != PHYS_FixedInSpace && root->mass < INFINITE_MASS;
    if (e.disturbed && hadPrevious && (!mover || !previousIsBody)) m_restChanged = true;
    c.prevCurrent = prevIsPose;
    if (!same) {
        if (mirrored && c.centred) {
            gcol::placeAtBody(m_shapes[size_t(e.first)], e.origin, e.rotation); // (its one shape: count 1)
        } else {
            const int count = g->shapeCount();
            if (count > c.capacity) moveToEnd(e, count);
            e.last = e.first + count;
            if (count > 0) g->writeWorldShapes(e.origin, e.rotation, &m_shapes[size_t(e.first)]);
        }
        if (!c.sized || c.sizedVersion != version || e.plane) { // sizes follow the shapes alone
            e.minDim = g->minDimension();
            if (!e.plane) c.bound = g->asInterface()->getBoundingRadius();
            c.centred = !e.plane && g->centredOnBody();
            c.sized = !e.plane;
            c.sizedVersion = version;
        }
        c.shapeVersion = version;
        c.selfAngleKnown = false;
        c.valid = !e.plane;
        if (!e.plane && e.first != e.last) {
            shapeBounds(m_shapes[size_t(e.first)], c.tight);
            for (int i = e.first + 1; i < e.last; ++i) {
                gcol::Aabb b;
                shapeBounds(m_shapes[size_t(i)], b);
                grow(c.tight, b);
            }
        }
    }
    if (e.first == e.last) { // an empty compound
        c.prevIsPose = false;
        return false;
    }
    const bool usePrevious = continuous && samePath;
    if (!same) c.prevIsSelf = false;
    if (usePrevious && !prevIsPose) {
        if (!previousKept) {
            e.prevOrigin = state.previousOrigin;
            e.prevRotation = state.previousRotation;
        }
        c.prevIsSelf = false;
    } else if (!c.prevIsSelf && continuous) { // (without sampling nothing reads the previous pose)
        e.prevOrigin = e.origin;
        e.prevRotation = e.rotation;
        c.prevIsSelf = true;
    }
    e.rotAngle = 0.0f;
    e.motion = 0.0f;
    e.moved = false;
    if (e.plane) return true; // infinite: no bounds, and nothing passes through a plane unseen
    if (usePrevious) {
        if (prevIsPose) {
            if (!c.selfAngleKnown) c.selfAngle = rotationAngle(e.rotation, e.rotation);
            c.selfAngleKnown = true;
            e.rotAngle = c.selfAngle;
        } else {
            e.rotAngle = rotationAngle(e.prevRotation, e.rotation);
        }
        e.motion = (e.origin - e.prevOrigin).length() + e.rotAngle * c.bound;
        e.moved = e.motion > 0.25f * e.minDim;
    }
    if (!e.moved) {
        if (!sameBits(e.box, c.tight)) copyBox(e.box, c.tight);
        return true;
    }
    copyBox(e.box, c.tight);
    {
        // Swept bounds: both end poses, inflated by how far rotation can carry a point off that path.
        m_scratchA.clear();
        if (mirrored && c.centred) { // its one shape, placed at the previous pose as the geometry would
            m_scratchA.push_back(m_shapes[size_t(e.first)]);
            gcol::placeAtBody(m_scratchA.back(), e.prevOrigin, e.prevRotation);
        } else {
            g->worldShapes(e.prevOrigin, e.prevRotation, m_scratchA);
        }
        for (const gcol::WorldShape& s : m_scratchA) {
            gcol::Aabb b;
            gcol::shapeAabb(s, b);
            grow(e.box, b);
        }
        float r = e.rotAngle * c.bound;
        e.box.min -= Vector(r, r, r);
        e.box.max += Vector(r, r, r);
    }
    return true;
}

namespace {

// Entries ahead. bench_compare's broadphase row (10,000 boxes, the tree's candidate stage after a move) does
// not settle between 4 and 12: run alone (a fresh heap), 1.43 ms at 4 against 1.85 at 12 (median of six
// each); after the rest of the benchmark (an aged heap), 1.75-1.82 at 4 against 1.50-1.52 at 12.
constexpr int kFetchAhead = 12;
using gcol::fetchAhead;

} // namespace

void SimpleCollisionSpace::gatherEntries(bool continuous) {
    const unsigned long long links = RBDynamics::attachmentEpoch();
    m_linksUnchanged = links == m_linksEpoch;
    m_linksEpoch = links;
    m_relaid = m_layoutDirty;
    if (m_layoutDirty) layOutEntries();
    m_changed.clear();
    m_restChanged = false;
    m_restingNewcomer = false;
    const int n = int(m_entries.size());
    for (int i = 0; i < n; ++i) {
        // The entries are walked in order, but each one's geometry, body and dynamics lie elsewhere: asked
        // for a few entries ahead, they arrive while this one is gathered (a call where nothing moved is
        // otherwise mostly waiting for them). A hint only: an address no longer valid is never read.
        // The entries themselves (more than a core's cache holds at 10,000) are asked for further ahead: the
        // lines of the one above are read to find those.
        if (i + 2 * kFetchAhead < n) {
            const char* later = reinterpret_cast<const char*>(&m_entries[size_t(i + 2 * kFetchAhead)]);
            for (int line = 0; line < 3; ++line) fetchAhead(later + 64 * line);
        }
        if (i + kFetchAhead < n) {
            const Entry& ahead = m_entries[size_t(i + kFetchAhead)];
            // The geometry's filter, body and space state (its first line, CollisionGeometry.h); when it
            // moved at the last call (and so probably at this one), also its previous pose and the fields of
            // its shape that follow (a box's half extents: up to byte 190). Every line of those 190 bytes
            // always: a moved call 10-25 % faster than the first line alone, a still one slower (a call that
            // reads little is bound by the lines it asks for).
            // Not the geometry of an entry that mirrors it, unless the entry moved at the last call (and so
            // probably moves now) and either its shapes do not simply sit at the body's origin (gatherEntry
            // reads them) or this is a whole call, whose end writes a moved geometry's space state (lines
            // that, not asked for here, made a 10,000-box pile's step about 1.5 % slower).
            const char* g = reinterpret_cast<const char*>(ahead.g);
            const bool mirrored = m_mirrors && ahead.cache.mirrored;
            if (!mirrored || (ahead.cache.reposed && (m_populating || !ahead.cache.centred))) {
                fetchAhead(g);
                if (ahead.cache.reposed)
                    for (int offset : {64, 128}) fetchAhead(g + offset);
            }
            if (const char* d = reinterpret_cast<const char*>(ahead.cache.dynamics)) {
                // Its pose, type, sleeping and teleports: its first 104 bytes (RBDynamics.h). (A third line,
                // where the body's allocation puts them across three, made no difference.)
                fetchAhead(d);
                fetchAhead(d + 64);
            }
        }
        Entry& e = m_entries[size_t(i)];
        const bool was = e.active;
        const HeldBox box(e.box);
        e.active = gatherEntry(e, continuous);
        if (was && !e.active) m_restChanged = true; // its body gone, or its pose no longer finite
        if (e.active != was || (e.active && !e.plane && !box.sameAs(e.box))) m_changed.push_back(i);
    }
}
