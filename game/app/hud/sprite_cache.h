#pragma once
#include <array>
#include <map>
#include <string>
#include <vector>

#include "files/assets.h"
#include "polar/render/image.h"

namespace polar::game {

// Sprite images by logical asset path, loaded on first use through the asset overlay.
//
// A missing or corrupt PNG must not stop the game: it is reported once (problems()) and drawn as a
// magenta box of the bounds' size, so the player sees where it is and the modder sees what is wrong.
class SpriteCache {
  public:
    explicit SpriteCache(const AssetFs& assets) : assets_(assets) {}
    const render::Image& get(const std::string& logical);
    // The sprite's shape in white (its alpha kept): a hit object's flash.
    const render::Image& silhouette(const std::string& logical);
    // Eight colours of the sprite, darkest first (its opaque texels' colours at evenly spaced ranks
    // of brightness): the debris of a broken thing is its own colours.
    using Palette = std::array<render::Color, 8>;
    const Palette& palette(const std::string& logical);
    // Forgets an image so it is read again (after a mod or hot reload changed it).
    void forget(const std::string& logical) {
        images_.erase(logical);
        silhouettes_.erase(logical);
        palettes_.erase(logical);
    }
    const std::vector<Error>& problems() const { return problems_; }

  private:
    const AssetFs& assets_;
    std::map<std::string, render::Image> images_;
    std::map<std::string, render::Image> silhouettes_;
    std::map<std::string, Palette> palettes_;
    std::vector<Error> problems_;
};

}  // namespace polar::game
