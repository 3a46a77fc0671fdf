// ManifoldReduce.h - keeps at most 4 of a face contact's candidate points, the ones that span the most area.
//
// Clipping a face against a face can leave up to 8 points; a solver needs at most 4 that keep the contact
// polygon's shape: the deepest, the farthest from it, then the two that enclose the most area either side.
#pragma once

#include "Shapes.h"

namespace gcol {

inline void reduceManifold(const ContactPoint* in, int n, const Vector& normal, ContactManifold& out) {
    if (n <= kMaxManifoldPoints) {
        for (int i = 0; i < n; ++i) out.points[i] = in[i];
        out.count = n;
        return;
    }
    int i0 = 0;
    for (int i = 1; i < n; ++i)
        if (in[i].depth > in[i0].depth) i0 = i;
    // Starts on a real index: with a NaN (or overflowed) position no distance compares greater, and an
    // index of -1 would read before the array.
    int i1 = i0 == 0 ? 1 : 0;
    float best = -1.0f;
    for (int i = 0; i < n; ++i) {
        float d = (in[i].pos - in[i0].pos).lengthSquared();
        if (i != i0 && d > best) best = d, i1 = i;
    }
    int i2 = -1, i3 = -1;
    float maxArea = 0.0f, minArea = 0.0f;
    for (int i = 0; i < n; ++i) {
        if (i == i0 || i == i1) continue;
        float area = dot(cross(in[i1].pos - in[i0].pos, in[i].pos - in[i0].pos), normal);
        if (i2 < 0 || area > maxArea) maxArea = area, i2 = i;
        if (i3 < 0 || area < minArea) minArea = area, i3 = i;
    }
    out.count = 0;
    int pick[4] = {i0, i1, i2, i3};
    for (int k = 0; k < 4; ++k) {
        bool dup = pick[k] < 0;
        for (int m = 0; m < k && !dup; ++m) dup = pick[m] == pick[k];
        if (!dup) out.points[out.count++] = in[pick[k]];
    }
}

} // namespace gcol
