// libFuzzer target: the bytes are an image file, decoded as loadRgbaImage decodes one (the format
// by its signature; libpng for PNG, SDL2_image for the rest). A decoded image has sides from 1 to
// 32767 and all its pixels; a refused one is one line naming the file.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_contract.h"
#include "platform/image_decoders.h"
#include "platform/image_format.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = "sprites/fuzz.img";
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    // Sides the limit allows but libFuzzer's 2 GB memory limit does not (a 30000×30000 header on a
    // few bytes of data): refused by the side limit's own tests, skipped here (over 4096 a side).
    const polar::ImageFormat format = polar::imageFormatOf(bytes);
    if (std::optional<polar::DeclaredSize> declared = polar::declaredSize(format, bytes);
        declared && (declared->width > 4096 || declared->height > 4096))
        return 0;
    polar::Result<polar::RgbaImage> image = polar::decodeImageBytes(path, bytes);
    if (!image) {
        const polar::Error& error = image.error();
        const std::string message = error.message();
        if (error.file != path) polar::fuzz::broken("the error does not name the file", message);
        if (error.what.empty()) polar::fuzz::broken("the error says nothing", message);
        if (message.rfind(path + ": ", 0) != 0)
            polar::fuzz::broken("the message does not start with the file", message);
        if (message.find('\n') != std::string::npos)
            polar::fuzz::broken("the message spans more than one line", message);
        return 0;
    }
    if (image->width < 1 || image->height < 1 || image->width > polar::kMaxImageSide ||
        image->height > polar::kMaxImageSide)
        polar::fuzz::broken("an image with impossible sides was accepted", std::to_string(image->width));
    if (image->pixels.size() != std::size_t(image->width) * std::size_t(image->height))
        polar::fuzz::broken("the image does not hold all its pixels", "");
    return 0;
}
