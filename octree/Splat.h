#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace texsplat::octree {

/// @brief One splat of the backend-neutral splat list: 32 bytes of plain floats.
///
/// The layout is fixed (two `vec4`s: position+size, premultiplied color+extinction) so that a
/// backend can upload `SplatList::splats().data()` as per-instance data without repacking:
/// attribute 0 at offset 0 (4 floats), attribute 1 at offset 16 (4 floats), stride 32.
struct Splat {
    /// @brief Centre of the splat in the volume's world space.
    glm::vec3 position{0.0f};
    /// @brief Extent relative to a finest-level voxel: 1 for a voxel, 2^k for a node k levels up
    /// (Laur & Hanrahan's coarser splats cover their whole node).
    float size = 1.0f;
    /// @brief Colour per unit length, ready to be premultiplied by the footprint's opacity.
    glm::vec3 color{0.0f};
    /// @brief Extinction coefficient tau (opacity per unit length) of the splat's medium.
    float extinction = 0.0f;
};

/// @brief One vector mark (Crawfis & Max 1993, "Combined Vector and Scalar Textures": "tiny
/// vector particles, or scratch marks"), as drawn by MarkSource: where it sits, which way
/// the field goes there and the medium of the voxel it stands for, in the splat node's local
/// space. The backends draw it for the view (render::ScreenMarks): oriented along the projected
/// vector, a head and a fading tail.
struct SplatMark {
    /// @brief Centre at animation phase 0: a random point in the cell of a non-empty voxel
    /// picked at random (MarkSource), so that the marks together fall at random, with no trace
    /// of the grid.
    glm::vec3 position{0.0f};
    /// @brief Where the mark is in its life cycle at animation phase 0, in [0, 1).
    float phase = 0.0f;
    /// @brief The field's vector at the voxel the mark sits in (finite; zero where a combined
    /// splat's voxel has no vector: the mark draws nothing).
    glm::vec3 vector{0.0f};
    /// @brief That voxel's classified extinction τ (per unit length).
    float extinction = 0.0f;
    /// @brief That voxel's classified colour.
    glm::vec3 color{0.0f};

    /// @brief Whether every member is equal (floats compared exactly).
    bool operator==(const SplatMark& other) const {
        return position == other.position && phase == other.phase && vector == other.vector &&
               extinction == other.extinction && color == other.color;
    }
};

static_assert(sizeof(Splat) == 8 * sizeof(float), "Splat must stay two packed vec4s");
static_assert(sizeof(SplatMark) == 11 * sizeof(float), "SplatMark must stay eleven packed floats");

/// @brief The splats of one view in back-to-front order, as a structure of arrays: the scalar
/// part (`splats()`, always present) and, for vector splats, their marks (`marks()`): splat i's
/// marks are `marks()[markBegin(i) .. markBegin(i + 1))`, zero or more each.
///
/// The list is what the octree hands to every backend (OpenGL instanced quads, the CPU splat
/// rasterizer): drawing in index order (a splat, then its marks) composites correctly with the
/// "over" operator.
class SplatList {
public:
    SplatList() = default;
    SplatList(const SplatList&) = default;
    SplatList(SplatList&&) noexcept = default;
    /// @brief Takes @p other's splats; the revision still moves on (see revision()).
    SplatList& operator=(const SplatList& other);
    /// @brief Takes @p other's splats; the revision still moves on (see revision()).
    SplatList& operator=(SplatList&& other) noexcept;
    ~SplatList() = default;

    /// @brief Reserves room for @p count splats, and for their mark offsets when @p withMarks.
    void reserve(std::size_t count, bool withMarks);

    /// @brief Appends a scalar splat; the list must not hold marks.
    void add(const Splat& splat);

    /// @brief Appends a vector splat with its @p markCount marks (none is fine); the list must
    /// hold marks for all its splats (or be empty).
    void add(const Splat& splat, const SplatMark* marks, std::size_t markCount);

    /// @brief Removes every splat and mark, keeping the allocated memory for the next frame.
    void clear();

    /// @brief Makes the list exactly @p count splats long, and with @p withMarks exactly
    /// @p markCount marks long with count + 1 mark offsets (else none), for a caller that writes
    /// them in place through the writable pointers, e.g. from several threads at once. What the
    /// list already held is kept (not cleared), so a list refilled with about as many splats as
    /// last frame writes no memory twice.
    void resize(std::size_t count, bool withMarks = false, std::size_t markCount = 0);

    /// @brief The splats, to be written in place (see resize()).
    [[nodiscard]] Splat* writableSplats() {
        ++mRevision;
        return mSplats.data();
    }

    /// @brief The marks, to be written in place (see resize()); null without marks.
    [[nodiscard]] SplatMark* writableMarks() {
        ++mRevision;
        return mMarks.data();
    }

    /// @brief The mark offsets (count + 1 of them, the first 0 and the last the mark count), to
    /// be written in place (see resize()); null without marks.
    [[nodiscard]] std::uint32_t* writableMarkBegins() {
        ++mRevision;
        return mMarkBegins.empty() ? nullptr : mMarkBegins.data();
    }

    /// @brief A number that grows with every change of the list (add(), clear(), resize(),
    /// assignment, the writable pointers): a list kept and refilled frame after frame is the
    /// same object with new splats, and what a backend uploaded of it is current while this is
    /// unchanged.
    [[nodiscard]] std::uint64_t revision() const { return mRevision; }

    /// @brief Number of splats.
    [[nodiscard]] std::size_t size() const { return mSplats.size(); }

    /// @brief Whether the list holds no splat.
    [[nodiscard]] bool isEmpty() const { return mSplats.empty(); }

    /// @brief Whether the list carries marks (`markBegins().size() == size() + 1`).
    [[nodiscard]] bool hasMarks() const { return !mMarkBegins.empty(); }

    /// @brief The scalar part, back to front.
    [[nodiscard]] const std::vector<Splat>& splats() const { return mSplats; }

    /// @brief The marks of all splats, splat by splat in the splats' order.
    [[nodiscard]] const std::vector<SplatMark>& marks() const { return mMarks; }

    /// @brief Where splat @p splat's marks start in marks() (@p splat may be size(): the mark
    /// count); 0 for a list without marks.
    [[nodiscard]] std::size_t markBegin(std::size_t splat) const {
        return mMarkBegins.empty() ? 0 : mMarkBegins[splat];
    }

    /// @brief The mark offsets (size() + 1), or empty for a list without marks.
    [[nodiscard]] const std::vector<std::uint32_t>& markBegins() const { return mMarkBegins; }

    /// @brief The most marks a list may hold: offsets are 32-bit.
    static constexpr std::size_t kMaxMarks = 0xffffffffu;

    /// @brief Bytes the list holds (its allocated capacity).
    [[nodiscard]] std::uint64_t memoryBytes() const {
        return mSplats.capacity() * sizeof(Splat) + mMarks.capacity() * sizeof(SplatMark) +
               mMarkBegins.capacity() * sizeof(std::uint32_t);
    }

private:
    std::vector<Splat> mSplats;
    std::vector<SplatMark> mMarks;
    std::vector<std::uint32_t> mMarkBegins; // size() + 1 offsets into mMarks, or none
    std::uint64_t mRevision = 0;
};

} // namespace texsplat::octree
