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

/// @brief The per-splat data that only vector splats need (Crawfis & Max 1993, "Vector
/// Splats": the direction and the texture table's row and column): 16 bytes, kept in a parallel
/// array so that scalar splat lists do not pay for it.
struct SplatVector {
    /// @brief The field's vector at the splat centre, in world space.
    glm::vec3 vector{0.0f};
    /// @brief Row of the vector splat table (the animation phase the splat starts at).
    std::uint16_t row = 0;
    /// @brief Column of the vector splat table (the foreshortening level, from view-space |v_z|).
    std::uint16_t column = 0;
};

static_assert(sizeof(Splat) == 8 * sizeof(float), "Splat must stay two packed vec4s");
static_assert(sizeof(SplatVector) == 4 * sizeof(float), "SplatVector must stay one packed vec4");

/// @brief The splats of one view in back-to-front order, as a structure of two arrays: the
/// scalar part (`splats()`, always present) and the vector part (`vectors()`, either empty or
/// exactly as long as `splats()`).
///
/// The list is what the octree hands to every backend (OpenGL instanced quads, the CPU splat
/// rasterizer): drawing in index order composites correctly with the "over" operator.
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

    /// @brief Reserves room for @p count splats, and for their vectors when @p withVectors.
    void reserve(std::size_t count, bool withVectors);

    /// @brief Appends a scalar splat; the list must not hold vectors.
    void add(const Splat& splat);

    /// @brief Appends a vector splat; the list must hold vectors for all its splats (or be
    /// empty).
    void add(const Splat& splat, const SplatVector& vector);

    /// @brief Removes every splat, keeping the allocated memory for the next frame.
    void clear();

    /// @brief Makes the list exactly @p count splats long (with as many vectors when
    /// @p withVectors, else none), for a caller that writes them in place through
    /// writableSplats() and writableVectors(), e.g. from several threads at once. Splats it
    /// already held are kept (not cleared), so a list refilled with about as many splats as
    /// last frame writes no memory twice.
    void resize(std::size_t count, bool withVectors);

    /// @brief The splats, to be written in place (see resize()).
    [[nodiscard]] Splat* writableSplats() {
        ++mRevision;
        return mSplats.data();
    }

    /// @brief The vectors, to be written in place (see resize()); null without vectors.
    [[nodiscard]] SplatVector* writableVectors() {
        ++mRevision;
        return mVectors.empty() ? nullptr : mVectors.data();
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

    /// @brief Whether the list carries the vector part (`vectors().size() == size()`).
    [[nodiscard]] bool hasVectors() const { return !mVectors.empty(); }

    /// @brief The scalar part, back to front.
    [[nodiscard]] const std::vector<Splat>& splats() const { return mSplats; }

    /// @brief Bytes the list holds (its allocated capacity).
    [[nodiscard]] std::uint64_t memoryBytes() const {
        return mSplats.capacity() * sizeof(Splat) + mVectors.capacity() * sizeof(SplatVector);
    }
    /// @brief The vector part, parallel to `splats()`, or empty for scalar splats.
    [[nodiscard]] const std::vector<SplatVector>& vectors() const { return mVectors; }

private:
    std::vector<Splat> mSplats;
    std::vector<SplatVector> mVectors;
    std::uint64_t mRevision = 0;
};

} // namespace texsplat::octree
