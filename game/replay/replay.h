#pragma once
// Replays: every part of recording, reading and verifying them (one header per part).
#include "replay/replay_format.h"
#include "replay/replay_game.h"
#include "replay/replay_parse.h"
#include "replay/replay_recorder.h"
#include "replay/replay_verify.h"
#include "replay/replay_writer.h"
