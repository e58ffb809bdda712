#pragma once
// Typed resources: at most one value per C++ type (the frame clock, the GL context, settings),
// held beside the entities, as in Bevy. Values are destroyed in reverse order of first insertion,
// so a resource inserted later (GL buffers) may depend on one inserted earlier (the GL context).
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "nimbus/ecs/detail/message.h"
#include "nimbus/ecs/type_id.h"

namespace nimbus::ecs {

class Resources {
public:
    Resources() = default;
    Resources(const Resources&) = delete;
    Resources& operator=(const Resources&) = delete;
    Resources(Resources&&) noexcept = default;
    Resources& operator=(Resources&& other) noexcept {
        if (this != &other) {
            clear();
            slots_ = std::move(other.slots_);
            order_ = std::move(other.order_);
        }
        return *this;
    }
    ~Resources() { clear(); }

    // Stores T{args...}, replacing (and destroying) any previous T; references to the old one dangle.
    template <class T, class... Args>
    T& insert(Args&&... args) {
        static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "resources are plain value types");
        std::unique_ptr<T> value;
        if constexpr (std::is_constructible_v<T, Args&&...>)
            value = std::make_unique<T>(std::forward<Args>(args)...);
        else
            value = std::unique_ptr<T>(new T{std::forward<Args>(args)...});
        const TypeId id = typeId<T>();
        while (id >= slots_.size()) slots_.emplace_back(nullptr, &noDelete);
        if (!slots_[id]) order_.push_back(id);
        T* raw = value.release();
        slots_[id] = Holder{raw, &deleteAs<T>};  // destroys the previous value, if any
        return *raw;
    }

    // Throws std::logic_error naming T when there is none: a system used a resource no plugin inserted.
    template <class T>
    T& get() {
        if (T* p = tryGet<T>()) return *p;
        throwMissing(typeName<T>());
    }
    template <class T>
    const T& get() const {
        if (const T* p = tryGet<T>()) return *p;
        throwMissing(typeName<T>());
    }

    template <class T>
    T* tryGet() {
        const TypeId id = typeId<T>();
        return id < slots_.size() ? static_cast<T*>(slots_[id].get()) : nullptr;
    }
    template <class T>
    const T* tryGet() const {
        const TypeId id = typeId<T>();
        return id < slots_.size() ? static_cast<const T*>(slots_[id].get()) : nullptr;
    }

    template <class T>
    bool contains() const {
        return tryGet<T>() != nullptr;
    }

    // Destroys the T, if any; returns whether there was one.
    template <class T>
    bool remove() {
        const TypeId id = typeId<T>();
        if (id >= slots_.size() || !slots_[id]) return false;
        slots_[id].reset();
        std::erase(order_, id);
        return true;
    }

    std::size_t size() const { return order_.size(); }

    // Destroys every resource, the most recently first-inserted first.
    void clear() {
        while (!order_.empty()) {
            slots_[order_.back()].reset();
            order_.pop_back();
        }
        slots_.clear();
    }

private:
    using Holder = std::unique_ptr<void, void (*)(void*)>;

    template <class T>
    static void deleteAs(void* p) {
        delete static_cast<T*>(p);
    }
    static void noDelete(void*) {}

    [[noreturn]] static void throwMissing(std::string_view type) {
        throw std::logic_error(detail::message({"resource ", type, " is missing: insert it first (insertResource<", type,
                                                ">(...), usually in a plugin's build)"}));
    }

    std::vector<Holder> slots_;  // indexed by TypeId; empty where that type has no resource
    std::vector<TypeId> order_;  // ids in order of first insertion
};

}  // namespace nimbus::ecs
