#include "nodes/bench/detail/SamplesPassed.h"

#include "scenegraph/gl/CheckGlError.h"

#include <epoxy/gl.h>

namespace texsplat::bench::detail {
namespace {

// The query object, deleted on every path out (draw may throw).
class Query {
public:
    Query() { glGenQueries(1, &mId); }
    ~Query() { glDeleteQueries(1, &mId); }
    Query(const Query&) = delete;
    Query& operator=(const Query&) = delete;
    GLuint id() const { return mId; }

private:
    GLuint mId = 0;
};

} // namespace

std::uint64_t countSamplesPassed(const std::function<void()>& draw) {
    const Query query;
    glBeginQuery(GL_SAMPLES_PASSED, query.id());
    try {
        draw();
    } catch (...) {
        glEndQuery(GL_SAMPLES_PASSED);
        throw;
    }
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 samples = 0;
    glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &samples);
    gl::checkGlError("countSamplesPassed()");
    return static_cast<std::uint64_t>(samples);
}

} // namespace texsplat::bench::detail
