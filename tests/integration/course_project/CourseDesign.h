// CourseDesign.h - what the project's Design.cpp provides to main.cpp.
#pragma once

class iContext;
class iDesign;
class iPhysicsScene;

struct CourseSetup {
    iDesign* design;
    iPhysicsScene* scene; // nullptr when the project has no simulator (collision-only)
    int frames;
};

CourseSetup createCourseDesign(iContext* context);
// 0 when every physical check the design made held; set while the design runs.
int courseVerdict();
