// libjpeg's errors for the library's JPEG reader and writer: its default
// handler prints and exits the process; here an error jumps back to the
// setjmp of the function that called libjpeg, with libjpeg's message kept.
#pragma once

#include <csetjmp>
#include <cstdio>
// jpeglib.h needs FILE and size_t declared before it.
#include <jpeglib.h>

namespace casteljau::detail {

/// libjpeg's error manager (first: libjpeg hands its address back), where
/// an error jumps back to, and its message.
struct JpegErrors {
    jpeg_error_mgr mgr;
    std::jmp_buf back;
    char message[JMSG_LENGTH_MAX] = {};

    /// Installs itself as the error manager of `c` (a compress or
    /// decompress struct, as libjpeg's functions take it), warnings not
    /// printed (a file cut short is a warning: what it held is used).
    void attach(j_common_ptr c) {
        c->err = jpeg_std_error(&mgr);
        mgr.error_exit = [](j_common_ptr j) {
            auto* e = reinterpret_cast<JpegErrors*>(j->err);
            j->err->format_message(j, e->message);
            std::longjmp(e->back, 1);
        };
        mgr.output_message = [](j_common_ptr) {};
    }
};

} // namespace casteljau::detail
