// An optional value kept on the heap: the size of one pointer when empty,
// with std::optional's interface and value semantics (copies copy the value).
// For large parts of the scene model that most objects leave out (a texture's
// normal pattern), so that a plain object stays small.
#pragma once

#include <memory>
#include <optional>
#include <utility>

namespace drt {

template <class T>
class HeapOptional {
public:
    HeapOptional() = default;
    HeapOptional(std::nullopt_t) {}
    HeapOptional(const T& value) : value_(std::make_unique<T>(value)) {}
    HeapOptional(T&& value) : value_(std::make_unique<T>(std::move(value))) {}
    HeapOptional(const std::optional<T>& value) {
        if (value) value_ = std::make_unique<T>(*value);
    }
    HeapOptional(std::optional<T>&& value) {
        if (value) value_ = std::make_unique<T>(std::move(*value));
    }
    HeapOptional(const HeapOptional& other) : value_(other ? std::make_unique<T>(*other) : nullptr) {}
    HeapOptional(HeapOptional&&) noexcept = default;
    HeapOptional& operator=(const HeapOptional& other) {
        if (this != &other) value_ = other ? std::make_unique<T>(*other) : nullptr;
        return *this;
    }
    HeapOptional& operator=(HeapOptional&&) noexcept = default;

    explicit operator bool() const { return value_ != nullptr; }
    bool has_value() const { return value_ != nullptr; }
    T& operator*() { return *value_; }
    const T& operator*() const { return *value_; }
    T* operator->() { return value_.get(); }
    const T* operator->() const { return value_.get(); }
    T& value() {
        if (!value_) throw std::bad_optional_access();
        return *value_;
    }
    const T& value() const {
        if (!value_) throw std::bad_optional_access();
        return *value_;
    }
    void reset() { value_.reset(); }
    template <class... Args>
    T& emplace(Args&&... args) {
        value_ = std::make_unique<T>(std::forward<Args>(args)...);
        return *value_;
    }
    operator std::optional<T>() const { return value_ ? std::optional<T>(*value_) : std::nullopt; }

private:
    std::unique_ptr<T> value_;
};

} // namespace drt
