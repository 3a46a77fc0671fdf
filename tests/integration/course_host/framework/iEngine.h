#ifndef _I_ENGINE_H_
#define _I_ENGINE_H_
// iEngine.h - the test host's engine interface, headless: run() steps a manual clock.

class iContext;

class iEngine {
public:
    virtual bool setup(int now) = 0;
    virtual int run(int frames, int msPerFrame) = 0;
    virtual void suspend() = 0;
    virtual void restore(int now) = 0;
    virtual void reset(int now) = 0;
    virtual int time() const = 0;
    virtual void Delete() const = 0;
};

extern "C" iEngine* CreateEngine(iContext* c);

#endif
