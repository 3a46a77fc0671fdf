// MathDeclarations.h - the course framework's Vector and Matrix value types.
//
// Conventions (shared by every module; README "Conventions" says the same):
//  * Units: metres, kilograms, seconds, radians. Engine time (`now`) is an int in milliseconds
//    (UNITS_PER_SEC = 1000 in ModelSettings.h); physics converts to seconds internally.
//  * Axes: x right, y up, z forward (into the screen). Left-handed, as Direct3D and the course framework.
//    cross() is the standard formula (x cross y = z), so v = w x r and torque = r x F hold unchanged; a
//    positive rotation about an axis turns clockwise seen from the positive axis looking at the origin.
//  * Row vectors: a point transforms as p' = p * M, so transforms compose left to right
//    (world = local * parent) and a homogeneous transform keeps its translation in m41, m42, m43.
//  * Matrix is 4x4, row-major (m11 m12 m13 m14 / m21 ...). Rotation matrices are orthonormal; the
//    physics and collision code never accept scale inside an orientation (see orthoNormalize).
//
// A superset of the course framework's MathDeclarations.h (fwk4gps): every type, member and macro the
// framework's file has (Vector, Matrix, Plane, Colour, Reflectivity, SQR, DEGTORAD, RADTODEG, LIMIT_RANGE,
// COLOUR_TO_ARGB, DEFAULT_SHININESS), with the same meanings, plus what the physics needs. A course project
// can overwrite its own copy with this one and keep compiling. Plain C++: no Eigen here or in
// MathDefinitions.h; the few heavy operations (inverse, orthoNormalize, inertia) live in GuardianMath.cpp.
// Supported: MODEL_Z_AXIS == NEAR_TO_FAR (the framework's default); see MathDefinitions.h.
// The framework's own include guard, not #pragma once: a project may hold this file twice (its copy and
// the package's Interfaces/ copy), and the guard keeps the two from both expanding.
#ifndef _MATH_DECLARATIONS_H_
#define _MATH_DECLARATIONS_H_

#include <cmath>
#include <cstddef>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

// --- the framework's macros ---
#define DEFAULT_SHININESS 10 // material reflectivity: Reflectivity's default power
#define SQR(x) ((x) * (x))
#define DEGTORAD(x) (((x)*M_PI) / 180.0f)
#define RADTODEG(x) (((x)*180.0f) / M_PI)
#define LIMIT_RANGE(low, value, high)                                                                        \
    {                                                                                                        \
        if (value < low)                                                                                     \
            value = low;                                                                                     \
        else if (value > high)                                                                               \
            value = high;                                                                                    \
    }

struct Matrix;

struct Vector {
    float x, y, z;

    Vector() : x(0), y(0), z(0) {}
    Vector(float nx, float ny, float nz) : x(nx), y(ny), z(nz) {}

    Vector operator+() const { return *this; }
    Vector operator-() const { return Vector(-x, -y, -z); }
    Vector& operator+=(const Vector& a) {
        x += a.x;
        y += a.y;
        z += a.z;
        return *this;
    }
    Vector& operator-=(const Vector& a) {
        x -= a.x;
        y -= a.y;
        z -= a.z;
        return *this;
    }
    // Overload on float so that ported `n *= -1` means negation (not the implicit Matrix(float)).
    Vector& operator*=(float s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    Vector& operator/=(float s);
    Vector& operator*=(const Matrix& m); // p = p * m, as a point (translation applied)

    float length() const;
    float lengthSquared() const { return x * x + y * y + z * z; }
    // Returns the unit vector along this one; the zero vector stays zero (no NaN).
    Vector normalize() const;
    bool isFinite() const;
};

inline Vector operator+(const Vector& a, const Vector& b) { return Vector(a.x + b.x, a.y + b.y, a.z + b.z); }
inline Vector operator-(const Vector& a, const Vector& b) { return Vector(a.x - b.x, a.y - b.y, a.z - b.z); }
inline Vector operator*(const Vector& v, float s) { return Vector(v.x * s, v.y * s, v.z * s); }
inline Vector operator*(float s, const Vector& v) { return Vector(v.x * s, v.y * s, v.z * s); }
// Component-wise product (Leung's addition to the framework); use dot() for the scalar product.
inline Vector operator*(const Vector& a, const Vector& b) { return Vector(a.x * b.x, a.y * b.y, a.z * b.z); }
// Dividing by zero returns the vector unchanged, as in the course framework.
inline Vector operator/(const Vector& v, float s) {
    return s == 0.0f ? v : Vector(v.x / s, v.y / s, v.z / s);
}
inline Vector& Vector::operator/=(float s) { return *this = *this / s; }
inline bool operator==(const Vector& a, const Vector& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
inline bool operator!=(const Vector& a, const Vector& b) { return !(a == b); }

inline float dot(const Vector& a, const Vector& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vector cross(const Vector& a, const Vector& b) {
    return Vector(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
float length(const Vector& v);
Vector normal(const Vector& v); // v / |v|; zero stays zero
// The component of a along b (zero when b is zero).
Vector projectOnTo(const Vector& a, const Vector& b);

struct Matrix {
    float m11, m12, m13, m14;
    float m21, m22, m23, m24;
    float m31, m32, m33, m34;
    float m41, m42, m43, m44;

    // All zeros, as in the course framework (use Matrix(1) for the identity).
    Matrix() : Matrix(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0) {}
    // diag(d, d, d, 1). Deliberately implicit, as in the course framework: Matrix m = 1; is the identity.
    Matrix(float d) : Matrix(d, 0, 0, 0, 0, d, 0, 0, 0, 0, d, 0, 0, 0, 0, 1) {}
    // diag(v.x, v.y, v.z, 1); implicit, as in the course framework.
    Matrix(const Vector& v) : Matrix(v.x, 0, 0, 0, 0, v.y, 0, 0, 0, 0, v.z, 0, 0, 0, 0, 1) {}
    Matrix(float a11, float a12, float a13, float a14, float a21, float a22, float a23, float a24, float a31,
           float a32, float a33, float a34, float a41, float a42, float a43, float a44)
        : m11(a11), m12(a12), m13(a13), m14(a14), m21(a21), m22(a22), m23(a23), m24(a24), m31(a31), m32(a32),
          m33(a33), m34(a34), m41(a41), m42(a42), m43(a43), m44(a44) {}

    float* data() { return &m11; }
    const float* data() const { return &m11; }
    // Element (row, col), both zero-based.
    float& operator()(int row, int col) { return data()[row * 4 + col]; }
    float operator()(int row, int col) const { return data()[row * 4 + col]; }

    Matrix& isIdentity(); // sets this matrix to the identity (the framework's name)
    Matrix& operator+=(const Matrix& a);
    Matrix& operator-=(const Matrix& a);
    Matrix& operator*=(const Matrix& a); // this = this * a

    Matrix transpose() const;
    Matrix inverse() const; // general 4x4 inverse; a singular matrix returns itself unchanged
    bool isFinite() const;

    // In-place transforms in the framework's sense: the rotation or scale is applied about parent-space
    // axes through this transform's own origin (the translation row is kept); translate moves along
    // parent-space axes.
    Matrix& translate(float x, float y, float z);
    Matrix& rotatex(float rad);
    Matrix& rotatey(float rad);
    Matrix& rotatez(float rad);
    Matrix& rotate(const Vector& axis, float rad);
    Matrix& rotate(const Matrix& rot);
    Matrix& scale(float x, float y, float z);
    // Replaces the rotation part with rot's, keeping the translation.
    Matrix& orient(const Matrix& rot);

    Vector position() const { return Vector(m41, m42, m43); } // the translation row
    Matrix rotation() const;                                  // the upper 3x3 with no translation
    // Transforms a direction: v * rotation(), translation not applied.
    Vector direction(const Vector& v) const;
    // The local axis 'x', 'y' or 'z' expressed in the parent space (a row of the rotation).
    Vector direction(char axis) const;
};

Matrix operator*(const Matrix& a, const Matrix& b);
Matrix operator+(const Matrix& a, const Matrix& b);
Matrix operator-(const Matrix& a, const Matrix& b);
Matrix operator*(const Matrix& a, float s);
Vector operator*(const Vector& v, const Matrix& m); // as a point: p * M, translation applied
// M * p as a column vector with the fourth column as translation (the framework has it; the physics does
// not use it: the framework's convention is p * M).
Vector operator*(const Matrix& m, const Vector& v);
bool operator==(const Matrix& a, const Matrix& b);
inline bool operator!=(const Matrix& a, const Matrix& b) { return !(a == b); }

// The framework's camera and scaling helpers (MathDefinitions.h), kept for course code that draws.
Matrix& scale(Matrix& m, float x, float y, float z); // sets m to diag(x, y, z, 1)
Matrix& scale(Matrix& m, const Vector& v);
Matrix view(const Vector& p, const Vector& d, const Vector& u); // eye p, looking at d, up u
Matrix projection(float fov, float aspect, float nearCp, float farCp);
Matrix projection(float minx, float maxx, float miny, float maxy, float nearCp, float farCp);
Matrix projToRhs(const Matrix& m);
Matrix orthographic(int w, int h);

// Generators (pure rotations/translations, no state).
Matrix rotatex(float rad);
Matrix rotatey(float rad);
Matrix rotatez(float rad);
Matrix rotate(const Vector& axis, float rad); // about a unit or non-unit axis through the origin
Matrix translation(float x, float y, float z);
Vector position(const Matrix& m);
Matrix rotation(const Matrix& m);
// The nearest rotation (polar decomposition) to m's 3x3 part, translation kept. Removes scale and shear;
// a reflection is turned into the nearest proper rotation.
Matrix orthoNormalize(const Matrix& m);
// True when m's 3x3 part is a proper rotation within tol (R R^T = I, det = +1).
bool isRotation(const Matrix& m, float tol = 1e-4f);

// --- inertia helpers (tensors are 3x3 in the upper-left of a Matrix, m44 = 1) ---
struct PointMass {
    Vector position; // in the body's local space
    float mass;
};
// Solid box of the given half extents ("radius", as COBB uses).
Matrix getBoxInertiaTensor(float mass, const Vector& halfExtents);
// Solid sphere.
Matrix getSphereInertiaTensor(float mass, float radius);
// Inertia of point masses about their own centre of mass (parallel-axis correct).
Matrix getInertiaTensor(const PointMass* points, size_t n);
// Centre of mass of point masses (zero when the total mass is zero).
Vector getCentreOfMass(const PointMass* points, size_t n);

// --- the framework's drawing types ---
// A plane n . p + d = 0. onPositiveSide keeps the framework's test (n . v + d < 0), which is what course
// code that calls it expects.
struct Plane {
    Vector n;
    float d;
    Plane(const Vector& v, float c) : n(v), d(c) {}
    bool onPositiveSide(const Vector& v) { return dot(n, v) + d < 0; }
    Vector normal() const { return n; }
    float constant() const { return d; }
};

struct Colour {
    float r, g, b, a;
    Colour(float red = 0, float grn = 0, float blu = 0, float alp = 1) : r(red), g(grn), b(blu), a(alp) {}
    operator const float*() const { return &r; }
};

#define COLOUR_TO_ARGB(c)                                                                                    \
    ((unsigned)((c.a) * 255) << 24 | (unsigned)((c.r) * 255) << 16 | (unsigned)((c.g) * 255) << 8 |          \
     (unsigned)((c.b) * 255))

// Ambient 70 % of the colour, diffuse the colour, white specular; power 0 means DEFAULT_SHININESS.
struct Reflectivity {
    Colour ambient, diffuse, specular;
    float power;
    Reflectivity(Colour c = Colour(), float p = 0)
        : ambient(c.r * 0.7f, c.g * 0.7f, c.b * 0.7f, c.a), diffuse(c), specular(1, 1, 1, c.a),
          power(p != 0 ? p : float(DEFAULT_SHININESS)) {}
    bool translucent() const { return ambient.a != 1 || diffuse.a != 1 || specular.a != 1; }
};

// The definitions come with the declarations so that no translation unit can use one without the other.
#include "MathDefinitions.h"

#endif // _MATH_DECLARATIONS_H_
