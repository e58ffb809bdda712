#pragma once
// A growable array stored in fixed-size pages. Unlike std::vector, growing never moves elements,
// so a reference to an element stays valid until that element itself is popped. Component storages
// rely on this: a system may emplace components while holding references to others of the same type.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace nimbus::ecs {

template <class T>
class PagedVector {
public:
    // About 16 KiB per page, a power of two so that indexing is a shift and a mask.
    static constexpr std::size_t kPageSize = std::bit_floor(std::max<std::size_t>(1, 16384 / sizeof(T)));

    PagedVector() = default;
    PagedVector(const PagedVector&) = delete;
    PagedVector& operator=(const PagedVector&) = delete;
    PagedVector(PagedVector&& other) noexcept
        : pages_(std::move(other.pages_)), size_(std::exchange(other.size_, 0)) {}
    PagedVector& operator=(PagedVector&& other) noexcept {
        if (this != &other) {
            clear();
            pages_ = std::move(other.pages_);
            size_ = std::exchange(other.size_, 0);
        }
        return *this;
    }
    ~PagedVector() { clear(); }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }

    T& operator[](std::size_t i) { return *slot(i); }
    const T& operator[](std::size_t i) const { return *slot(i); }
    T& back() { return *slot(size_ - 1); }

    template <class... Args>
    T& emplace_back(Args&&... args) {
        if (size_ == pages_.size() * kPageSize) pages_.push_back(std::unique_ptr<Page>(new Page));  // uninitialised bytes
        T* p = rawSlot(size_);
        if constexpr (std::is_constructible_v<T, Args&&...>)
            ::new (static_cast<void*>(p)) T(std::forward<Args>(args)...);
        else  // aggregates with brace-only initialisation
            ::new (static_cast<void*>(p)) T{std::forward<Args>(args)...};
        ++size_;
        return *std::launder(p);
    }

    void pop_back() {
        --size_;
        std::destroy_at(slot(size_));
    }

    // Destroys every element and frees the pages.
    void clear() {
        while (size_ > 0) pop_back();
        pages_.clear();
    }

private:
    struct Page {
        alignas(T) std::byte bytes[sizeof(T) * kPageSize];
    };

    T* rawSlot(std::size_t i) const {
        return reinterpret_cast<T*>(pages_[i / kPageSize]->bytes + sizeof(T) * (i % kPageSize));
    }
    T* slot(std::size_t i) const { return std::launder(rawSlot(i)); }

    std::vector<std::unique_ptr<Page>> pages_;
    std::size_t size_ = 0;
};

}  // namespace nimbus::ecs
