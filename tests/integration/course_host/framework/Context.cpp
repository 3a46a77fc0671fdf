// Context.cpp - the test host's context.
#include "iContext.h"

class Context : public iContext {
    int values[GF_NO_INTEGERS];

public:
    Context() {
        for (int i = 0; i < GF_NO_INTEGERS; ++i) values[i] = 0;
        values[GF_WN_WIDTH] = 800;
        values[GF_WN_HEIGHT] = 600;
    }
    void set(Integer key, int value) { values[key] = value; }
    int get(Integer key) const { return values[key]; }
    void Delete() const { delete this; }
};

iContext* CreateContext() { return new Context(); }
