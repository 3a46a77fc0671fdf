// Frame.h - the stand-in framework's concrete reference frame (the course framework's Frame).
//
// iPhysicsFrame derives from Frame (as in the seed), and the framework's objects do too. A Frame keeps T and
// a parent pointer; world() walks the chain. It does not track children: delete children first. A course
// project has its own Frame; the engine uses only its public iFrame members and its default constructor.
#pragma once

#include "MathDeclarations.h"
#include "iFrame.h"
#include "iUtilities.h"

class Frame : public iFrame {
public:
    Frame() : m_T(1), m_parent(nullptr) {}
    Frame(const Frame& src) : iFrame(), m_T(src.m_T), m_parent(src.m_parent) {}
    Frame& operator=(const Frame& src) {
        m_T = src.m_T;
        m_parent = src.m_parent;
        return *this;
    }
    virtual ~Frame() {}

    void translate(float x, float y, float z) override { m_T.translate(x, y, z); }
    void scale(float x, float y, float z) override { m_T.scale(x, y, z); }
    void rotatex(float rad) override { m_T.rotatex(rad); }
    void rotatey(float rad) override { m_T.rotatey(rad); }
    void rotatez(float rad) override { m_T.rotatez(rad); }
    void rotate(const Vector& axis, float rad) override { m_T.rotate(axis, rad); }
    void rotate(const Matrix& rot) override { m_T.rotate(rot); }
    void orient(const Matrix& rot) override { m_T.orient(rot); }

    Vector position() const override { return world().position(); }
    Matrix rotation() const override { return world().rotation(); }
    Vector orientation(char axis) const override { return rotation().direction(axis); }
    Vector orientation(const Vector& v) const override { return rotation().direction(v); }
    Matrix world() const override { return m_parent ? m_T * m_parent->world() : m_T; }
    Vector relativePosition() const override { return m_T.position(); }

    // T itself (not on iFrame: the course framework has no such members).
    const Matrix& transform() const { return m_T; }
    void setTransform(const Matrix& t) {
        if (t.isFinite())
            m_T = t;
        else
            error(L"Frame::setTransform: non-finite transform refused");
    }

    void attachTo(iFrame* newParent) override {
        for (const iFrame* p = newParent; p; p = p->parent()) {
            if (p == this) {
                error(L"Frame::attachTo: attaching a frame to itself or a descendant refused");
                return;
            }
        }
        Matrix w = world();
        m_parent = newParent;
        m_T = newParent ? w * newParent->world().inverse() : w;
    }
    iFrame* parent() const override { return m_parent; }
    void Delete() const override { delete this; }

protected:
    Matrix m_T;
    iFrame* m_parent;
};

extern "C" inline iFrame* CreateFrame() { return new Frame(); }
