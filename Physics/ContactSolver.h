// ContactSolver.h - resolves one step's contacts with sequential impulses, then corrects leftover overlap.
//
// Velocity phase (solveVelocities), after forces changed velocities and before positions move:
//   group contacts into manifolds per geometry pair (up to 4 points), optionally (keepDistance > 0,
//   off by default) keep last step's points that the detector dropped but that are apart by less than
//   keepDistance (persistent manifold; such a point may close its gap within the step, no more), match each
//   point with last step's point at the same body-local anchor and warm start with its impulses, then sweep,
//   alternately forward and backward: per manifold, two friction impulses per point (Coulomb, clamped to
//   mu * normal impulse), then one normal impulse per point (accumulated, clamped >= 0). Restitution
//   targets -e * v_n only when the approach speed exceeds a threshold, so resting contacts do not jitter.
// Position phase (correctPositions), after positions moved: non-linear Gauss-Seidel (Box2D v2's choice).
//   Each point's separation is recomputed from its anchors on both bodies; a fraction of the overlap beyond
//   the slop is removed by moving the poses directly, until nothing overlaps beyond it or the iterations
//   run out. Velocities are untouched, so the correction adds no energy (Baumgarte's velocity bias would
//   make bounces and stacks gain it). A body left overlapping by more than slop + 1 mm is marked settling,
//   so the scene does not put it to sleep with the overlap frozen in.
// References: Catto, "Iterative Dynamics with Temporal Coherence" (GDC 2005) and "Solver2D" (2024);
// Bullet's persistent manifold (contact breaking threshold).
#pragma once

#include "ContactManifold.h"
#include "MathBridge.h"
#include "iContactSettings.h"

#include <cstddef>
#include <unordered_map>
#include <vector>

struct CollisionContact;
struct RBDynamics;

namespace physics {

struct SolverSettings {
    int velocityIterations = 10;
    int positionIterations = 10;       // at most (stops once nothing overlaps beyond the slop)
    float restitutionThreshold = 1.0f; // m/s of approach below which a contact does not bounce
    float slop = 0.005f;               // m of overlap left alone (keeps contacts alive between steps)
    float positionFraction = 0.2f;     // share of the overlap removed per position iteration
    float maxCorrection = 0.2f;        // m moved per position iteration at most
    float matchDistance = 0.05f;       // m: a point within this of last step's anchor inherits its impulses
    // m: a point that came apart by less than this is kept (0: never). Off by default: it helps the 10-box
    // tower at 10 iterations (top drift 3.3 cm vs 5.3 cm) but keeps it swaying at 40-100 iterations (KE
    // 0.1 J at 10 s vs 0.0002 J without), so it still feeds energy somewhere; see keepPoints().
    float keepDistance = 0.0f;
    bool warmStart = true;
    CombineRule friction = COMBINE_Sum;    // the seed's rule: the two bodies' values added
    CombineRule restitution = COMBINE_Max; // a superball bounces off anything
};

float combine(CombineRule rule, float a, float b);

// How the solver reads and moves a body. The default works on a single RBDynamics; the scene supplies
// composite mass properties for bodies with attachments.
class SolverBodyAccess {
public:
    virtual ~SolverBodyAccess() = default;
    virtual SolverBody load(RBDynamics* root) const;
    // Writes back v and w (and the angular momentum that goes with w).
    virtual void storeVelocity(const SolverBody& b) const;
    // Whether a body of last step is still there to be touched (nullptr: the static world).
    virtual bool alive(const RBDynamics* root) const { return !root; }
    // Moves the pose by dp and turns it by the small rotation vector dtheta about b.com.
    virtual void movePose(SolverBody& b, const Vec3& dp, const Vec3& dtheta) const;
};

class ContactSolver {
public:
    void setSettings(const SolverSettings& s) { m_settings = s; }
    const SolverSettings& settings() const { return m_settings; }

    void solveVelocities(const CollisionContact* contacts, size_t count, float dt,
                         const SolverBodyAccess& access);
    void correctPositions(const SolverBodyAccess& access);

    // Forgets last step's impulses (no warm start next step).
    void clear();

    size_t manifoldCount() const { return m_manifolds.size(); }
    // Deepest overlap seen by the last solveVelocities / left after the last correctPositions.
    float maxPenetrationBefore() const { return m_maxDepthBefore; }
    float maxPenetrationAfter() const { return m_maxDepthAfter; }
    // The bodies touching in the last step, as pairs of roots (for islands and sleeping).
    const std::vector<Manifold>& manifolds() const { return m_manifolds; }
    // The bodies of the last solveVelocities (the scene advances their poses before correctPositions).
    std::vector<SolverBody>& bodies() { return m_bodies; }

private:
    int bodyIndex(RBDynamics* root, const SolverBodyAccess& access);
    void buildManifolds(const CollisionContact* contacts, size_t count, const SolverBodyAccess& access);
    void keepPoints(const SolverBodyAccess& access,
                    const std::unordered_map<PairKey, size_t, PairKeyHash>& reported);
    void prepare(float dt);
    void warmStart();
    void solveOnce(bool backward);
    void storeImpulses();

    SolverSettings m_settings;
    std::vector<SolverBody> m_bodies;
    std::unordered_map<const RBDynamics*, int> m_bodyIndex;
    std::vector<Manifold> m_manifolds;
    std::unordered_map<PairKey, Manifold, PairKeyHash> m_previous;
    std::vector<Manifold> m_previousList; // the same, in solving order (for a deterministic keep)
    float m_maxDepthBefore = 0, m_maxDepthAfter = 0;
};

} // namespace physics
