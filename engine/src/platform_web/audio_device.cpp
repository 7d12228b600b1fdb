#include "polar/platform/audio_device.h"

#include <emscripten.h>

#include <cstdint>
#include <vector>

// WebAudio: a ScriptProcessorNode asks for each block on the page's thread and the mixer fills
// it, interleaved, in the device's buffer; the node spreads it over its channels. A browser starts
// an AudioContext only after the player's first key press, click or tap, so it is resumed then.
EM_JS(int, polarWebAudioOpen,
      (int sampleRate, int channels, int frames, std::intptr_t fill, void* self, float* buffer), {
          var Context = window.AudioContext || window.webkitAudioContext;
          if (!Context) return 0;
          var context;
          try {
              context = new Context({sampleRate : sampleRate});
          } catch (e) {
              return 0;
          }
          var size = 256;
          while (size < frames && size < 16384) size *= 2;
          var node = context.createScriptProcessor(size, 0, channels);
          var device = {context : context, node : node, playing : false};
          var call =
              (typeof getWasmTableEntry != 'undefined') ? getWasmTableEntry(fill) : wasmTable.get(fill);
          node.onaudioprocess = function(e) {
              var out = e.outputBuffer;
              for (var done = 0; done < out.length; done += frames) {
                  var n = Math.min(frames, out.length - done);
                  var base = buffer >> 2;
                  if (device.playing) {
                      call(self, buffer, n * channels * 4);
                  } else {
                      HEAPF32.fill(0, base, base + n * channels);
                  }
                  for (var c = 0; c < channels; ++c) {
                      var data = out.getChannelData(c);
                      for (var i = 0; i < n; ++i) data[done + i] = HEAPF32[base + i * channels + c];
                  }
              }
          };
          node.connect(context.destination);
          // A browser lets a page start its sound only in the handler of the player's gesture
          // (a key, a click, a finger lifted); a page hidden or left stops it until the next one.
          var resume = function() {
              if (context.state != 'running') context.resume();
          };
          var suspend = function() {
              if (context.state == 'running') context.suspend();
          };
          var hidden = function() {
              if (document.hidden) suspend();
          };
          device.listeners = [[window, 'keydown', resume], [window, 'pointerdown', resume],
                              [window, 'pointerup', resume], [window, 'touchend', resume],
                              [window, 'blur', suspend], [document, 'visibilitychange', hidden]];
          device.listeners.forEach(function(l) { l[0].addEventListener(l[1], l[2]); });
          device.resume = resume;
          Module.polarAudio = Module.polarAudio || [null];
          Module.polarAudio.push(device);
          return Module.polarAudio.length - 1;
      });

EM_JS(void, polarWebAudioPlay, (int id, int playing), {
    var device = Module.polarAudio[id];
    device.playing = playing != 0;
    if (playing) device.resume();
});

EM_JS(void, polarWebAudioClose, (int id), {
    var device = Module.polarAudio[id];
    if (!device) return;
    device.node.disconnect();
    device.node.onaudioprocess = null;
    device.listeners.forEach(function(l) { l[0].removeEventListener(l[1], l[2]); });
    device.context.close();
    Module.polarAudio[id] = null;
});

namespace polar::platform {
namespace {

// Each device's block of interleaved samples, which the mixer fills and the node reads.
std::vector<std::vector<float>>& buffers() {
    static std::vector<std::vector<float>> all(1);
    return all;
}

}  // namespace

Result<std::unique_ptr<AudioDevice>> AudioDevice::open(const AudioSettings& settings, AudioMixer mixer) {
    std::unique_ptr<AudioDevice> device(new AudioDevice());
    device->sampleRate_ = settings.sampleRate;
    device->channels_ = settings.channels;
    device->mixer_ = std::move(mixer);
    std::vector<float> buffer(static_cast<std::size_t>(settings.framesPerBlock) * settings.channels);
    const int id = polarWebAudioOpen(settings.sampleRate, settings.channels, settings.framesPerBlock,
                                     reinterpret_cast<std::intptr_t>(&AudioDevice::callback), device.get(),
                                     buffer.data());
    if (id == 0)
        return Error{"the audio device", 0, 0, "this browser has no WebAudio", "a browser with WebAudio"};
    if (buffers().size() <= static_cast<std::size_t>(id)) buffers().resize(static_cast<std::size_t>(id) + 1);
    buffers()[static_cast<std::size_t>(id)] = std::move(buffer);  // the heap block stays where it is
    device->device_ = static_cast<std::uint32_t>(id);
    return device;
}

AudioDevice::~AudioDevice() {
    if (device_ == 0) return;
    polarWebAudioClose(static_cast<int>(device_));
    buffers()[device_].clear();
    buffers()[device_].shrink_to_fit();
}

void AudioDevice::start() {
    polarWebAudioPlay(static_cast<int>(device_), 1);
}

void AudioDevice::pause() {
    polarWebAudioPlay(static_cast<int>(device_), 0);
}

void AudioDevice::callback(void* self, unsigned char* stream, int bytes) {
    auto& device = *static_cast<AudioDevice*>(self);
    device.mixer_(reinterpret_cast<float*>(stream), bytes / (4 * device.channels_));
}

}  // namespace polar::platform
