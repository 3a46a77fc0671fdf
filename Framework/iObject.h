// iObject.h - a headless game object: a Frame with a bounding box where a windowed framework would draw.
//
// The seed's sample attaches such an object to a physics frame: o->attachTo(f).
#pragma once

#include "Frame.h"

class iObject : public Frame {
public:
    // Local-space axis-aligned bounds of what would be drawn.
    virtual Vector minimum() const = 0;
    virtual Vector maximum() const = 0;
    virtual iObject* clone() const = 0;
    virtual void suspend() = 0;
    virtual void restore(int now) = 0;
    virtual void release() = 0;
    virtual void Delete() const = 0;
};

extern "C" iObject* CreateBox(float minx, float miny, float minz, float maxx, float maxy, float maxz);
extern "C" iObject* CreateSphere(float radius);
