// SoftBody.cpp - a soft body (iSoftBody.h, seed 000's SoftBody): a body at every grid place its mask holds,
// joined by springs to its structural, shear and bend neighbours, each at rest at its length at creation.
//
// The bodies are made as physics::RigidBody directly, not with CreateRigidBody, which would add them to the
// active scene: they are in no scene until addToScene. They have no collision geometry (Physics/ never sees
// Collision/): the game gives them shapes.
//
// The bodies are a BodyGroup: one deleted by anyone else (its scene's Delete()) reads nullptr from then on,
// and the soft body's own Delete() skips it instead of deleting it twice.
#include "BodyGroup.h"

#include "iPhysicsScene.h"
#include "iSoftBody.h"
#include "iSpring.h"
#include "iUtilities.h"

#include <climits>
#include <cmath>
#include <string>
#include <vector>

namespace physics {

namespace {

class SoftBody final : public iSoftBody {
public:
    SoftBody(const bool* mask, int columns, int rows, const Vector& corner, const Vector& columnStep,
             const Vector& rowStep, float bodyMass, float stiffness, float damping)
        : m_columns(columns), m_rows(rows), m_grid(size_t(columns) * size_t(rows), -1) {
        const float radius = 0.5f * std::fmin(columnStep.length(), rowStep.length());
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < columns; ++c) {
                if (!mask[r * columns + c]) continue;
                m_grid[size_t(r * columns + c)] = int(m_bodies.size());
                m_group.makeBody(corner + columnStep * float(c) + rowStep * float(r), bodyMass, radius);
            }
        // Each unordered pair once: structural, shear (both diagonals of the cell), bend.
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < columns; ++c) {
                join(c, r, c + 1, r, stiffness, damping);
                join(c, r, c, r + 1, stiffness, damping);
                join(c, r, c + 1, r + 1, stiffness, damping);
                join(c + 1, r, c, r + 1, stiffness, damping);
                join(c, r, c + 2, r, stiffness, damping);
                join(c, r, c, r + 2, stiffness, damping);
            }
    }
    bool complete() const { return !m_failed; }

    int getColumns() const override { return m_columns; }
    int getRows() const override { return m_rows; }
    int getBodyCount() const override { return int(m_bodies.size()); }
    iRigidBody* getBody(int i) const override {
        return i >= 0 && size_t(i) < m_bodies.size() ? m_bodies[size_t(i)] : nullptr;
    }
    iRigidBody* getBodyAt(int column, int row) const override {
        if (column < 0 || column >= m_columns || row < 0 || row >= m_rows) return nullptr;
        const int i = m_grid[size_t(row * m_columns + column)];
        return i < 0 ? nullptr : m_bodies[size_t(i)];
    }
    int getSpringCount() const override { return int(m_springs.size()); }
    iSpring* getSpring(int i) const override {
        return i >= 0 && size_t(i) < m_springs.size() ? m_springs[size_t(i)] : nullptr;
    }

    // Checked once here so that a refused value leaves every spring as it was.
    bool setTightness(float k) override {
        if (!(k >= 0) || !std::isfinite(k)) {
            error(L"iSoftBody::setTightness: needs a finite k >= 0; refused");
            return false;
        }
        for (iSpring* spring : m_springs) spring->setStiffness(k);
        return true;
    }
    bool setDamping(float c) override {
        if (!(c >= 0) || !std::isfinite(c)) {
            error(L"iSoftBody::setDamping: needs a finite c >= 0; refused");
            return false;
        }
        for (iSpring* spring : m_springs) spring->setDamping(c);
        return true;
    }

    bool addToScene(iPhysicsScene* scene) override { return m_group.addTo(scene, L"iSoftBody"); }
    void killAll() override { m_group.killAll(); }

    // The springs first, then the bodies; each Delete() waits for the end of a running step by itself.
    void Delete() const override {
        for (iSpring* spring : m_springs) spring->Delete();
        m_group.deleteAll();
        delete this;
    }

private:
    ~SoftBody() override = default;
    // A spring between places (c1, r1) and (c2, r2) when both hold a body.
    void join(int c1, int r1, int c2, int r2, float k, float damping) {
        iRigidBody* a = getBodyAt(c1, r1);
        iRigidBody* b = getBodyAt(c2, r2);
        if (!a || !b) return;
        const Vector pa = a->getDynamics().position, pb = b->getDynamics().position;
        iSpring* spring = CreateSpring(a, b, pa, pb, (pb - pa).length(), k, damping);
        if (spring)
            m_springs.push_back(spring);
        else
            m_failed = true; // cannot happen with the checked input; the factory says so
    }

    int m_columns, m_rows;
    std::vector<int> m_grid; // row by row, each place's index in m_bodies (-1 where the mask is false)
    BodyGroup m_group;       // the bodies alone, row by row
    std::vector<iRigidBody*>& m_bodies = m_group.bodies;
    std::vector<iSpring*> m_springs;
    bool m_failed = false;
};

// Why the input is refused, or nullptr when it makes a soft body.
const wchar_t* softBodyInputProblem(const bool* mask, int columns, int rows, const Vector& corner,
                                    const Vector& columnStep, const Vector& rowStep, float bodyMass,
                                    float stiffness, float damping) {
    if (!mask) return L"no mask";
    if (columns <= 0 || rows <= 0 || columns > INT_MAX / rows) return L"columns and rows must be positive";
    bool anyBody = false;
    for (int i = 0; i < columns * rows && !anyBody; ++i) anyBody = mask[i];
    if (!anyBody) return L"the mask holds no body";
    if (!corner.isFinite() || !columnStep.isFinite() || !rowStep.isFinite())
        return L"corner and steps must be finite";
    // Degenerate: a zero step, or steps along one line (the grid's places would collapse onto a line).
    const float a = columnStep.length(), b = rowStep.length();
    if (!(a > 0) || !(b > 0) || !(cross(columnStep, rowStep).length() > 1e-6f * a * b))
        return L"the steps must be non-zero and not parallel";
    const Vector farCorner = corner + columnStep * float(columns - 1) + rowStep * float(rows - 1);
    if (!farCorner.isFinite()) return L"the grid reaches beyond the float range";
    if (!(bodyMass > 0) || !std::isfinite(bodyMass)) return L"the body mass must be finite and > 0";
    if (!isValidInertiaTensor(getSphereInertiaTensor(bodyMass, 0.5f * std::fmin(a, b))))
        return L"the mass and steps give no valid inertia";
    if (!(stiffness >= 0) || !std::isfinite(stiffness) || !(damping >= 0) || !std::isfinite(damping))
        return L"stiffness and damping must be finite and >= 0";
    return nullptr;
}

} // namespace

} // namespace physics

extern "C" iSoftBody* CreateSoftBody(const bool* mask, int columns, int rows, const Vector& corner,
                                     const Vector& columnStep, const Vector& rowStep, float bodyMass,
                                     float stiffness, float damping) {
    if (const wchar_t* problem = physics::softBodyInputProblem(mask, columns, rows, corner, columnStep,
                                                               rowStep, bodyMass, stiffness, damping)) {
        error((std::wstring(L"CreateSoftBody: ") + problem + L"; refused").c_str());
        return nullptr;
    }
    physics::SoftBody* body =
        new physics::SoftBody(mask, columns, rows, corner, columnStep, rowStep, bodyMass, stiffness, damping);
    if (!body->complete()) {
        body->Delete();
        return nullptr;
    }
    return body;
}
