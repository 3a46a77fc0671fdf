#ifndef _I_CONTEXT_H_
#define _I_CONTEXT_H_
// iContext.h - the test host's context: its own keys and getters, none of them the physics'.

typedef enum Integer { GF_WN_WIDTH, GF_WN_HEIGHT, GF_FR_NUM, GF_NO_INTEGERS } Integer;

class iContext {
public:
    virtual void set(Integer key, int value) = 0;
    virtual int get(Integer key) const = 0;
    virtual void Delete() const = 0;
};

extern "C" iContext* CreateContext();

#endif
