#ifndef _I_FRAME_H_
#define _I_FRAME_H_
// iFrame.h - the test host's frame interface: the course framework's members only.

struct Vector;
struct Matrix;

class iFrame {
public:
    virtual void translate(float x, float y, float z) = 0;
    virtual void scale(float x, float y, float z) = 0;
    virtual void rotatex(float rad) = 0;
    virtual void rotatey(float rad) = 0;
    virtual void rotatez(float rad) = 0;
    virtual void orient(const Matrix& rot) = 0;
    virtual Vector position() const = 0;
    virtual Matrix rotation() const = 0;
    virtual Vector orientation(char axis) const = 0;
    virtual Matrix world() const = 0;
    virtual void attachTo(iFrame* parent) = 0;
};

#endif
