#pragma once
// The seed's header for a bound: programs that include it get polar/bound.h, where Bound is defined
// and CollisionRadii is its alias.
#include "polar/bound.h"
