#include "nodes/distributed/Compositor.h"

#include "scenegraph/Assert.h"
#include "scenegraph/Error.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <utility>

namespace texsplat::distributed {
namespace {

using image::ImageRegion;

// "over" on premultiplied colours.
inline glm::vec4 over(const glm::vec4& front, const glm::vec4& back) {
    return front + (1.0f - front.a) * back;
}

// Four floats of header (x, y, width, height: whole numbers below 2^24, exact in float), then
// the pixels: one message of a layer's part.
constexpr std::size_t kHeader = 4;

// The pixels of `layer` in `part` (within its region), row after row, to `out`: a message's
// or a layer's pixels.
void copyPart(const ImageLayer& layer, const ImageRegion& part, void* out) {
    const std::size_t rowBytes = sizeof(glm::vec4) * static_cast<std::size_t>(part.width);
    auto* bytes = static_cast<unsigned char*>(out);
    for (int y = part.y; rowBytes > 0 && y < part.y + part.height; ++y, bytes += rowBytes) {
        std::memcpy(bytes, &layer.at(part.x, y), rowBytes);
    }
}

std::vector<float> pack(const ImageLayer& layer, const ImageRegion& window) {
    const ImageRegion part = layer.isEmpty() ? ImageRegion{} : intersect(layer.region, window);
    const auto width = static_cast<std::size_t>(part.width);
    const auto height = static_cast<std::size_t>(part.height);
    std::vector<float> message(kHeader + 4 * width * height);
    message[0] = static_cast<float>(part.x);
    message[1] = static_cast<float>(part.y);
    message[2] = static_cast<float>(part.width);
    message[3] = static_cast<float>(part.height);
    copyPart(layer, part, message.data() + kHeader);
    return message;
}

// The part of `layer` inside `window`.
ImageLayer cut(const ImageLayer& layer, const ImageRegion& window) {
    ImageLayer part;
    part.region = layer.isEmpty() ? ImageRegion{} : intersect(layer.region, window);
    part.pixels.resize(std::size_t(part.region.width) * std::size_t(part.region.height));
    copyPart(layer, part.region, part.pixels.data());
    return part;
}

ImageLayer unpack(const std::vector<float>& message) {
    ImageLayer layer;
    layer.region = {static_cast<int>(message[0]), static_cast<int>(message[1]),
                    static_cast<int>(message[2]), static_cast<int>(message[3])};
    const std::size_t count = (message.size() - kHeader) / 4;
    layer.pixels.resize(count);
    if (count > 0) { // an empty part's storage is null, which memcpy() may not be given
        std::memcpy(layer.pixels.data(), message.data() + kHeader, sizeof(glm::vec4) * count);
    }
    return layer;
}

// Band `part` of `parts` of the image's rows [first, end): the rows shared in proportion.
ImageRegion band(int width, int first, int end, int parts, int part) {
    const long long rows = end - first;
    const int begin = first + static_cast<int>(rows * part / parts);
    const int stop = first + static_cast<int>(rows * (part + 1) / parts);
    return {0, begin, width, stop - begin};
}

// `layers` (back to front) composited over the region their pixels cover, transparent where
// none has a pixel.
ImageLayer compositeLayers(const std::vector<ImageLayer>& layers) {
    int x0 = INT_MAX;
    int y0 = INT_MAX;
    int x1 = INT_MIN;
    int y1 = INT_MIN;
    for (const ImageLayer& layer : layers) {
        if (!layer.isEmpty()) {
            x0 = std::min(x0, layer.region.x);
            y0 = std::min(y0, layer.region.y);
            x1 = std::max(x1, layer.region.x + layer.region.width);
            y1 = std::max(y1, layer.region.y + layer.region.height);
        }
    }
    ImageLayer result;
    if (x0 >= x1) {
        return result;
    }
    result.region = {x0, y0, x1 - x0, y1 - y0};
    result.pixels.assign(static_cast<std::size_t>(result.region.width) *
                             static_cast<std::size_t>(result.region.height),
                         glm::vec4(0.0f));
    for (const ImageLayer& layer : layers) {
        if (layer.isEmpty()) {
            continue;
        }
        for (int y = layer.region.y; y < layer.region.y + layer.region.height; ++y) {
            const glm::vec4* front = &layer.at(layer.region.x, y);
            glm::vec4* back = &result.pixels[static_cast<std::size_t>(y - y0) *
                                                 static_cast<std::size_t>(result.region.width) +
                                             static_cast<std::size_t>(layer.region.x - x0)];
            for (int x = 0; x < layer.region.width; ++x) {
                back[x] = over(front[x], back[x]);
            }
        }
    }
    return result;
}

// Receives the message `source` sent with `tag`, whatever its length.
std::vector<float> receive(MPI_Comm comm, int source, int tag) {
    MPI_Status status;
    MPI_Probe(source, tag, comm, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_FLOAT, &count);
    std::vector<float> message(static_cast<std::size_t>(count));
    MPI_Recv(message.data(), count, MPI_FLOAT, source, tag, comm, MPI_STATUS_IGNORE);
    return message;
}

// MPI_Op: inout = in over inout, pixel by pixel (in comes from the lower rank: the nearer).
void overPixels(void* in, void* inout, int* count, MPI_Datatype* /*type*/) {
    const auto* front = static_cast<const glm::vec4*>(in);
    auto* back = static_cast<glm::vec4*>(inout);
    for (int i = 0; i < *count; ++i) {
        back[i] = over(front[i], back[i]);
    }
}

constexpr int kGatherTag = 1000;

} // namespace

std::string toString(Compositing method) {
    return method == Compositing::RadixK ? "radix-k" : "reduce";
}

Compositing parseCompositing(const std::string& text, const std::string& option) {
    if (text == "radix-k") {
        return Compositing::RadixK;
    }
    if (text == "reduce") {
        return Compositing::Reduce;
    }
    throw DataError(option + ": expected radix-k or reduce, got '" + text + "'");
}

Compositor::Compositor(MPI_Comm comm, int width, int height, Compositing method)
    : mComm(comm), mWidth(width), mHeight(height), mMethod(method) {
    MPI_Comm_rank(comm, &mRank);
    MPI_Comm_size(comm, &mSize);
}

std::vector<int> Compositor::radixRounds(int ranks) {
    std::vector<int> factors;
    for (int factor = 2; ranks > 1; ++factor) {
        while (ranks % factor == 0) {
            factors.push_back(factor);
            ranks /= factor;
        }
    }
    std::vector<int> rounds;
    for (std::size_t i = 0; i < factors.size(); ++i) {
        if (factors[i] == 2 && i + 1 < factors.size() && factors[i + 1] == 2) {
            rounds.push_back(4);
            ++i;
        } else {
            rounds.push_back(factors[i]);
        }
    }
    return rounds;
}

std::uint64_t Compositor::memoryBound(const ImageLayer& layer) const {
    // The layer's copy in messages, the pieces received and their composite, and on rank 0 the
    // whole image: at most three images' worth.
    const std::uint64_t image = std::uint64_t(mWidth) * std::uint64_t(mHeight) * sizeof(glm::vec4);
    return 3 * image + layer.pixels.size() * sizeof(glm::vec4);
}

image::Pixels Compositor::composite(ImageLayer layer,
                                             const std::vector<int>& backToFront) {
    TEXSPLAT_ASSERT(static_cast<int>(backToFront.size()) == mSize,
                    "Compositor::composite(): one position per rank");
    return mMethod == Compositing::RadixK ? compositeRadixK(std::move(layer), backToFront)
                                          : compositeReduce(layer, backToFront);
}

image::Pixels Compositor::compositeRadixK(ImageLayer layer,
                                                   const std::vector<int>& backToFront) {
    const int position = static_cast<int>(std::find(backToFront.begin(), backToFront.end(), mRank) -
                                          backToFront.begin());
    int first = 0;
    int end = mHeight;
    int stride = 1;
    int tag = 0;
    // Positions that differ in one digit (mixed radix, the rounds' sizes) form a group; the
    // digit orders the group back to front, since each member holds the composite of a run of
    // positions and the runs follow each other.
    for (const int k : radixRounds(mSize)) {
        const int digit = (position / stride) % k;
        const int base = position - digit * stride;
        std::vector<std::vector<float>> sent(static_cast<std::size_t>(k));
        std::vector<MPI_Request> requests;
        for (int member = 0; member < k; ++member) {
            if (member == digit) {
                continue;
            }
            const int rank = backToFront[static_cast<std::size_t>(base + member * stride)];
            std::vector<float>& message = sent[static_cast<std::size_t>(member)];
            message = pack(layer, band(mWidth, first, end, k, member));
            requests.emplace_back();
            MPI_Isend(message.data(), static_cast<int>(message.size()), MPI_FLOAT, rank, tag, mComm,
                      &requests.back());
        }
        const ImageRegion kept = band(mWidth, first, end, k, digit);
        std::vector<ImageLayer> parts(static_cast<std::size_t>(k));
        parts[static_cast<std::size_t>(digit)] = cut(layer, kept);
        layer = ImageLayer{}; // all of it is in the messages and the part kept
        for (int member = 0; member < k; ++member) {
            if (member != digit) {
                const int rank = backToFront[static_cast<std::size_t>(base + member * stride)];
                parts[static_cast<std::size_t>(member)] = unpack(receive(mComm, rank, tag));
            }
        }
        MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
        layer = compositeLayers(parts);
        first = kept.y;
        end = kept.y + kept.height;
        stride *= k;
        ++tag;
    }
    // Each rank holds the finished pixels of its rows: rank 0 gathers them.
    if (mRank != 0) {
        std::vector<float> message = pack(layer, {0, first, mWidth, end - first});
        MPI_Send(message.data(), static_cast<int>(message.size()), MPI_FLOAT, 0, kGatherTag, mComm);
        return {};
    }
    image::Pixels image(
        static_cast<std::size_t>(mWidth) * static_cast<std::size_t>(mHeight), glm::vec4(0.0f));
    const auto place = [&](const ImageLayer& part) {
        for (int y = part.region.y; y < part.region.y + part.region.height; ++y) {
            std::memcpy(&image[static_cast<std::size_t>(y) * static_cast<std::size_t>(mWidth) +
                               static_cast<std::size_t>(part.region.x)],
                        &part.at(part.region.x, y),
                        sizeof(glm::vec4) * std::size_t(part.region.width));
        }
    };
    place(layer);
    for (int rank = 1; rank < mSize; ++rank) {
        place(unpack(receive(mComm, rank, kGatherTag)));
    }
    return image;
}

image::Pixels Compositor::compositeReduce(const ImageLayer& layer,
                                                   const std::vector<int>& backToFront) {
    std::vector<int> position(static_cast<std::size_t>(mSize));
    for (int i = 0; i < mSize; ++i) {
        position[static_cast<std::size_t>(backToFront[static_cast<std::size_t>(i)])] = i;
    }
    // The nearest brick's rank first: MPI reduces a non-commutative operation in rank order.
    const auto orderedRank = [&](int rank) {
        return mSize - 1 - position[static_cast<std::size_t>(rank)];
    };
    MPI_Comm ordered = MPI_COMM_NULL;
    MPI_Comm_split(mComm, 0, orderedRank(mRank), &ordered);
    MPI_Datatype pixel = MPI_DATATYPE_NULL;
    MPI_Type_contiguous(4, MPI_FLOAT, &pixel);
    MPI_Type_commit(&pixel);
    MPI_Op overOp = MPI_OP_NULL;
    MPI_Op_create(&overPixels, 0, &overOp);
    image::Pixels image(
        static_cast<std::size_t>(mWidth) * static_cast<std::size_t>(mHeight), glm::vec4(0.0f));
    for (int y = 0; y < layer.region.height && !layer.isEmpty(); ++y) {
        std::memcpy(&image[static_cast<std::size_t>(layer.region.y + y) * std::size_t(mWidth) +
                           static_cast<std::size_t>(layer.region.x)],
                    &layer.at(layer.region.x, layer.region.y + y),
                    sizeof(glm::vec4) * std::size_t(layer.region.width));
    }
    const int root = orderedRank(0);
    const int count = mWidth * mHeight;
    if (mRank == 0) {
        MPI_Reduce(MPI_IN_PLACE, image.data(), count, pixel, overOp, root, ordered);
    } else {
        MPI_Reduce(image.data(), nullptr, count, pixel, overOp, root, ordered);
        image.clear();
    }
    MPI_Op_free(&overOp);
    MPI_Type_free(&pixel);
    MPI_Comm_free(&ordered);
    return image;
}

} // namespace texsplat::distributed
