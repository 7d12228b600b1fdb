#pragma once
#include <map>

#include "rules/game.h"

namespace polar::game {

// Object transforms as they were before the last tick, so a frame can be drawn between two ticks.
class Interpolation {
  public:
    void capture(const World& world);
    // The transform `alpha` of the way from the captured one to the current one.
    Transform at(const GameObject& object, double alpha) const;

  private:
    std::map<ObjectId, Transform> previous_;
};

}  // namespace polar::game
