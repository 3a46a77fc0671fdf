// Context.cpp - the framework's settings store behind iContext.
#include "iContext.h"

#include "MathDefinitions.h"

namespace {

class Context final : public iContext {
public:
    void set(Integer key, int value) override { store(m_ints, m_intSet, key, value); }
    void set(Float key, float value) override { store(m_floats, m_floatSet, key, value); }
    void set(VectorId key, const Vector& value) override { store(m_vectors, m_vectorSet, key, value); }
    int get(Integer key) const override { return valid(key, GF_NO_INTEGERS) ? m_ints[key] : 0; }
    float get(Float key) const override { return valid(key, GF_NO_FLOATS) ? m_floats[key] : 0.0f; }
    Vector get(VectorId key) const override { return valid(key, GF_NO_VECTORS) ? m_vectors[key] : Vector(); }
    bool isSet(Integer key) const override { return valid(key, GF_NO_INTEGERS) && m_intSet[key]; }
    bool isSet(Float key) const override { return valid(key, GF_NO_FLOATS) && m_floatSet[key]; }
    bool isSet(VectorId key) const override { return valid(key, GF_NO_VECTORS) && m_vectorSet[key]; }
    void Delete() const override { delete this; }

private:
    static bool valid(int key, int count) { return key >= 0 && key < count; }
    template <class T, size_t N, class K>
    static void store(T (&values)[N], bool (&flags)[N], K key, const T& v) {
        if (!valid(key, int(N))) return;
        values[key] = v;
        flags[key] = true;
    }

    int m_ints[GF_NO_INTEGERS] = {};
    bool m_intSet[GF_NO_INTEGERS] = {};
    float m_floats[GF_NO_FLOATS] = {};
    bool m_floatSet[GF_NO_FLOATS] = {};
    Vector m_vectors[GF_NO_VECTORS];
    bool m_vectorSet[GF_NO_VECTORS] = {};
};

} // namespace

extern "C" iContext* CreateContext() { return new Context(); }
