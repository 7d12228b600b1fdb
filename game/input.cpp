#include "input.h"

#include "display.h"

namespace polar::game {
namespace {

constexpr Sint16 kStickDeadZone = 12000;
constexpr Sint16 kTriggerPressed = 8000;

}  // namespace

Input::Input() {
    for (int i = 0; i < SDL_NumJoysticks(); ++i)
        if (SDL_IsGameController(i)) openController(i);
}

Input::~Input() {
    for (auto& [id, pad] : pads_) SDL_GameControllerClose(pad);
}

void Input::openController(int deviceIndex) {
    SDL_GameController* pad = SDL_GameControllerOpen(deviceIndex);
    if (!pad) return;
    SDL_JoystickID id = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(pad));
    if (pads_.count(id)) {
        SDL_GameControllerClose(pad);
        return;
    }
    pads_[id] = pad;
}

void Input::handle(const SDL_Event& event) {
    switch (event.type) {
        case SDL_QUIT:
            commands_.quit = true;
            break;
        case SDL_CONTROLLERDEVICEADDED:
            openController(event.cdevice.which);
            break;
        case SDL_CONTROLLERDEVICEREMOVED:
            if (auto it = pads_.find(event.cdevice.which); it != pads_.end()) {
                SDL_GameControllerClose(it->second);
                pads_.erase(it);
            }
            break;
        case SDL_KEYDOWN:
            if (event.key.repeat) break;
            switch (event.key.keysym.sym) {
                case SDLK_ESCAPE:
                    commands_.back = commands_.pause = true;
                    break;
                case SDLK_p:
                    commands_.pause = true;
                    break;
                case SDLK_RETURN:
                case SDLK_KP_ENTER:
                    if (!(event.key.keysym.mod & KMOD_ALT)) commands_.confirm = true;
                    break;
                case SDLK_SPACE:
                    commands_.confirm = true;
                    break;
                case SDLK_F1:
                    commands_.debugOverlay = true;
                    break;
                case SDLK_F5:
                    commands_.reload = true;
                    break;
                case SDLK_UP:
                case SDLK_w:
                    commands_.up = true;
                    break;
                case SDLK_DOWN:
                case SDLK_s:
                    commands_.down = true;
                    break;
                case SDLK_LEFT:
                case SDLK_a:
                    commands_.left = true;
                    break;
                case SDLK_RIGHT:
                case SDLK_d:
                    commands_.right = true;
                    break;
                default:
                    break;
            }
            break;
        case SDL_CONTROLLERBUTTONDOWN:
            switch (event.cbutton.button) {
                case SDL_CONTROLLER_BUTTON_START:
                    commands_.pause = true;
                    break;
                case SDL_CONTROLLER_BUTTON_A:
                    commands_.confirm = true;
                    break;
                case SDL_CONTROLLER_BUTTON_BACK:
                    commands_.back = true;
                    break;
                case SDL_CONTROLLER_BUTTON_DPAD_UP:
                    commands_.up = true;
                    break;
                case SDL_CONTROLLER_BUTTON_DPAD_DOWN:
                    commands_.down = true;
                    break;
                case SDL_CONTROLLER_BUTTON_DPAD_LEFT:
                    commands_.left = true;
                    break;
                case SDL_CONTROLLER_BUTTON_DPAD_RIGHT:
                    commands_.right = true;
                    break;
                default:
                    break;
            }
            break;
        default:
            break;
    }
}

Actions Input::actions() const {
    Actions actions = 0;
    const Uint8* keys = SDL_GetKeyboardState(nullptr);
    if (keys[SDL_SCANCODE_LEFT] || keys[SDL_SCANCODE_A]) actions |= kTurnLeft;
    if (keys[SDL_SCANCODE_RIGHT] || keys[SDL_SCANCODE_D]) actions |= kTurnRight;
    if (keys[SDL_SCANCODE_UP] || keys[SDL_SCANCODE_W]) actions |= kThrust;
    if (keys[SDL_SCANCODE_SPACE]) actions |= kFire;
    for (const auto& [id, pad] : pads_) {
        Sint16 x = SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_LEFTX);
        Sint16 y = SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_LEFTY);
        if (x < -kStickDeadZone || SDL_GameControllerGetButton(pad, SDL_CONTROLLER_BUTTON_DPAD_LEFT))
            actions |= kTurnLeft;
        if (x > kStickDeadZone || SDL_GameControllerGetButton(pad, SDL_CONTROLLER_BUTTON_DPAD_RIGHT))
            actions |= kTurnRight;
        if (y < -kStickDeadZone || SDL_GameControllerGetButton(pad, SDL_CONTROLLER_BUTTON_B) ||
            SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_TRIGGERRIGHT) > kTriggerPressed)
            actions |= kThrust;
        if (SDL_GameControllerGetButton(pad, SDL_CONTROLLER_BUTTON_A)) actions |= kFire;
    }
    return actions;
}

Input::Commands Input::takeCommands() {
    Commands out = commands_;
    commands_ = Commands{};
    return out;
}

Input::Commands Input::pollEvents(Display& display) {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
        if (display.handleEvent(event)) continue;
        handle(event);
    }
    return takeCommands();
}

}  // namespace polar::game
