#include "app/hud/lettering.h"

#include <cctype>

namespace polar::game {

std::string upperCase(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

}  // namespace polar::game
