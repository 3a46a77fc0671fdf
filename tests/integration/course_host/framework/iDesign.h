#ifndef _I_DESIGN_H_
#define _I_DESIGN_H_
// iDesign.h - the test host's design interface, shaped like the course framework's (v1 lifecycle).

class iContext;

class iDesign {
public:
    virtual void initialize(int now) = 0;
    virtual void reset(int now) = 0;
    virtual void restore(int now) = 0;
    virtual void update(int now) = 0;
    virtual void suspend() = 0;
    virtual void Delete() const = 0;
};

extern "C" iDesign* CreateDesign(iContext* c);

#endif
