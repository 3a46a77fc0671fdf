#ifndef _FRAME_H_
#define _FRAME_H_
// Frame.h - the test host's reference frame: T and parent are private, as in the course framework.
#include "MathDeclarations.h"
#include "iFrame.h"

class Frame : public iFrame {
    Matrix T;       // relative to the parent, or world
    iFrame* parent; // nullptr for a root frame

public:
    Frame();
    void translate(float x, float y, float z) { T.translate(x, y, z); }
    void scale(float x, float y, float z) { T.scale(x, y, z); }
    void rotatex(float rad) { T.rotatex(rad); }
    void rotatey(float rad) { T.rotatey(rad); }
    void rotatez(float rad) { T.rotatez(rad); }
    void orient(const Matrix& rot) { T.orient(rot); }
    Vector position() const;
    Matrix rotation() const;
    Vector orientation(char axis) const;
    Matrix world() const;
    void attachTo(iFrame* newParent);
    virtual ~Frame() {}
};

#endif
