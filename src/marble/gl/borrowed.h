#pragma once
#include <epoxy/gl.h>

namespace marble::gl {

// The name of a GL object someone else owns (the G-buffer's depth texture handed to a later
// pass, a caller's framebuffer): bound or attached here, never deleted here, and never compared
// -- it has no operator==, so `a == b` does not compile. GL reuses names: once the owner deletes
// its object, the next one created may get the same name, so an equal name does not mean the
// same object (and a framebuffer still attached to the deleted one keeps that one alive and
// keeps showing it). Whoever holds a Borrowed therefore re-attaches what it is handed each time
// instead of skipping the attachment when the name looks unchanged; the driver compares the
// objects themselves (attaching the same object again costs a framebuffer revalidation, which
// is microseconds next to a pass).
class Borrowed {
public:
  Borrowed() = default;
  explicit Borrowed(GLuint id) : id_(id) {}
  GLuint id() const { return id_; }

private:
  GLuint id_ = 0;
};

}  // namespace marble::gl
