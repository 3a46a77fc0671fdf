#ifndef _ENGINE_H_
#define _ENGINE_H_
// Engine.h - the test host's engine: creates the design, runs the frame loop, forwards the lifecycle.
#include "iEngine.h"

class iContext;
class iDesign;

class Engine : public iEngine {
    iContext* context;
    iDesign* design;
    int now;
    bool active;
    ~Engine();

public:
    Engine(iContext* c);
    bool setup(int now);
    int run(int frames, int msPerFrame);
    void suspend();
    void restore(int now);
    void reset(int now);
    int time() const { return now; }
    void Delete() const { delete this; }
};

#endif
