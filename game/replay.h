#pragma once
// Replays: every part of recording, reading and verifying them (one header per part).
#include "replay_format.h"
#include "replay_game.h"
#include "replay_parse.h"
#include "replay_recorder.h"
#include "replay_verify.h"
#include "replay_writer.h"
