// iContactSettings.h - how two bodies' friction and restitution combine into one contact's coefficients.
//
// Chosen per scene (iPhysicsScene::setFrictionRule / setRestitutionRule). The seed's rule for friction is
// the sum of the two values; restitution defaults to the larger of the two.
#pragma once

enum CombineRule : int {   // a fixed type: any int is a value, so a bad one is refused, not undefined
    COMBINE_Sum,           // a + b (the seed's friction rule; the default for friction)
    COMBINE_Average,       // (a + b) / 2
    COMBINE_Max,           // the larger (the default for restitution: a superball bounces off anything)
    COMBINE_Min,           // the smaller
    COMBINE_Product,       // a * b
    COMBINE_GeometricMean, // sqrt(a * b) (Box2D's friction rule)
};
