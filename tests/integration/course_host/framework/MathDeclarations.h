#ifndef _MATH_DECLARATIONS_H_
#define _MATH_DECLARATIONS_H_
// MathDeclarations.h - the test host's own math types, shaped like the course framework's (a package's
// copy overwrites this file; the host's code must keep compiling against that copy).
#include <cmath>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#define DEFAULT_SHININESS 10
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
    Vector(float a, float b, float c) : x(a), y(b), z(c) {}
    Vector operator+() { return *this; }
    Vector operator-() { return Vector(-x, -y, -z); }
    Vector& operator+=(const Vector& a) {
        x += a.x, y += a.y, z += a.z;
        return *this;
    }
    Vector& operator-=(const Vector& a) {
        x -= a.x, y -= a.y, z -= a.z;
        return *this;
    }
    float length() const { return std::sqrt(x * x + y * y + z * z); }
};
inline Vector operator+(const Vector& a, const Vector& b) { return Vector(a.x + b.x, a.y + b.y, a.z + b.z); }
inline Vector operator-(const Vector& a, const Vector& b) { return Vector(a.x - b.x, a.y - b.y, a.z - b.z); }
inline Vector operator*(float s, const Vector& a) { return Vector(s * a.x, s * a.y, s * a.z); }
inline Vector operator*(const Vector& a, float s) { return Vector(s * a.x, s * a.y, s * a.z); }
inline float dot(const Vector& a, const Vector& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vector cross(const Vector& a, const Vector& b) {
    return Vector(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

struct Matrix {
    float m11, m12, m13, m14, m21, m22, m23, m24, m31, m32, m33, m34, m41, m42, m43, m44;
    Matrix() : Matrix(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0) {}
    Matrix(float d) : Matrix(d, 0, 0, 0, 0, d, 0, 0, 0, 0, d, 0, 0, 0, 0, 1) {}
    Matrix(float a, float b, float c, float d, float e, float f, float g, float h, float i, float j, float k,
           float l, float m, float n, float o, float p)
        : m11(a), m12(b), m13(c), m14(d), m21(e), m22(f), m23(g), m24(h), m31(i), m32(j), m33(k), m34(l),
          m41(m), m42(n), m43(o), m44(p) {}
    Matrix& translate(float x, float y, float z);
    Matrix& rotatex(float rad);
    Matrix& rotatey(float rad);
    Matrix& rotatez(float rad);
    Matrix& orient(const Matrix& rot);
    Matrix& scale(float x, float y, float z);
    Matrix transpose() const;
    Vector position() const { return Vector(m41, m42, m43); }
    Matrix rotation() const {
        return Matrix(m11, m12, m13, 0, m21, m22, m23, 0, m31, m32, m33, 0, 0, 0, 0, 1);
    }
};
Matrix operator*(const Matrix& a, const Matrix& b);
Vector operator*(const Vector& v, const Matrix& m);

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

struct Reflectivity {
    Colour ambient, diffuse, specular;
    float power;
    Reflectivity(Colour c = Colour(), float p = 0)
        : ambient(c.r * 0.7f, c.g * 0.7f, c.b * 0.7f, c.a), diffuse(c), specular(1, 1, 1, c.a),
          power(p != 0 ? p : DEFAULT_SHININESS) {}
    bool translucent() const { return ambient.a != 1 || diffuse.a != 1 || specular.a != 1; }
};

#endif
