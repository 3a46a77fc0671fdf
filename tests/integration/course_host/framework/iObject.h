#ifndef _I_OBJECT_H_
#define _I_OBJECT_H_
// iObject.h - the test host's drawable object: a frame with a material and a size; draw() records it.
#include "Frame.h"

class iObject : public Frame {
public:
    virtual void draw() = 0;
    virtual const Reflectivity& material() const = 0;
    virtual void Delete() const = 0;
};

extern "C" iObject* CreateSphere(float radius, const Reflectivity& r);
extern "C" iObject* CreateBox(float minx, float miny, float minz, float maxx, float maxy, float maxz,
                              const Reflectivity& r);
// The headless display: how many draws were recorded, and the last drawn object's world position.
int drawsRecorded();
Vector lastDrawnPosition();

#endif
