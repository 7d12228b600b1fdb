#pragma once
// The older header for a bound's outline: programs that include it get polar/bound_outline.h, where
// boundOutline and boundSamplePoints are declared and radiiOutline and radiiSamplePoints forward to them.
#include "polar/bound_outline.h"
