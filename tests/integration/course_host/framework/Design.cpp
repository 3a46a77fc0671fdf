// Design.cpp - the test host's own game design: coloured objects, a floor plane, a turning box, drawn each
// frame. It knows nothing of physics, and must build unchanged after a package is merged in.
#include "MathDefinitions.h"
#include "iContext.h"
#include "iDesign.h"
#include "iObject.h"

class Design : public iDesign {
    iContext* context;
    iObject* ball;
    iObject* box;
    Plane floor;
    Matrix camera;
    int frames;

public:
    Design(iContext* c) : context(c), ball(0), box(0), floor(Vector(0, 1, 0), 0), camera(1), frames(0) {}
    void initialize(int) {
        Colour red(1, 0, 0);
        ball = CreateSphere(1, Reflectivity(red));
        ball->translate(0, 5, 0);
        box = CreateBox(-1, -1, -1, 1, 1, 1, Reflectivity(Colour(0, 0, 1, 0.5f), 20));
        camera = view(Vector(0, 2, -10), Vector(0, 0, 0), Vector(0, 1, 0));
    }
    void reset(int) { frames = 0; }
    void restore(int) {}
    void update(int) {
        box->rotatey(DEGTORAD(1.0f));
        if (!floor.onPositiveSide(ball->position())) ball->draw();
        if (box->material().translucent()) box->draw();
        ++frames;
    }
    void suspend() {}
    void Delete() const {
        ball->Delete();
        box->Delete();
        delete this;
    }
};

iDesign* CreateDesign(iContext* c) { return new Design(c); }
