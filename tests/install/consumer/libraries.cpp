// Every installed library's headers compile from the prefix alone, and the program links.
#include <cstdio>

#include <polar/polar.h>
#ifdef CONSUMER_USES_RENDER
#include <polar/render/render.h>
#endif
#ifdef CONSUMER_USES_PLATFORM
#if __has_include(<polar/platform/platform.h>)
#include <polar/platform/platform.h>
#else
#include <polar/platform/image_file.h>
#endif
#endif
#ifdef CONSUMER_USES_AUTHORING
#include <polar/authoring/bounds_check.h>
#include <polar/authoring/bounds_gen.h>
#include <polar/authoring/random_scene.h>
#endif

int main() {
    std::printf("libraries linked\n");
}
