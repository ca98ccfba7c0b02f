// Computed_once<T>: a value computed on first use and then kept, safe when several threads ask for it at
// once. The whole diagram's parallel loops share vertices whose exact coordinates and rounding a
// predicate's exact stage computes lazily; plain lazy members would race there.
//
// A thread that finds no value computes one and publishes it with one compare-and-swap. A thread that loses
// the race discards its own copy and uses the winner's: the computation is deterministic, so both are
// equal. A copy of the object shares the value published so far (a reference count), and computes its own
// if it had none. Reading a published value is one acquire load, no lock.
#pragma once

#include <atomic>
#include <utility>

namespace apollonius {

template <class T>
class Computed_once {
 public:
  Computed_once() = default;
  explicit Computed_once(T value) : node_(new Node{std::move(value)}) {}
  Computed_once(const Computed_once& other) : node_(other.acquire_node()) {}
  Computed_once(Computed_once&& other) noexcept : node_(other.node_.exchange(nullptr, std::memory_order_relaxed)) {}
  // Assignment, like any write to an object, must not run beside other uses of the same object.
  Computed_once& operator=(const Computed_once& other) {
    if (this != &other) release(node_.exchange(other.acquire_node(), std::memory_order_acq_rel));
    return *this;
  }
  Computed_once& operator=(Computed_once&& other) noexcept {
    if (this != &other)
      release(node_.exchange(other.node_.exchange(nullptr, std::memory_order_relaxed), std::memory_order_acq_rel));
    return *this;
  }
  ~Computed_once() { release(node_.load(std::memory_order_relaxed)); }

  // Forgets the value (a later get_or_compute computes it again). Like assignment, must not run beside other
  // uses of the same object.
  void reset() { release(node_.exchange(nullptr, std::memory_order_acq_rel)); }

  // The value if published, else null.
  const T* get() const {
    const Node* node = node_.load(std::memory_order_acquire);
    return node == nullptr ? nullptr : &node->value;
  }

  // The value, computed by compute() (returning a T) unless published already.
  template <class Compute>
  const T& get_or_compute(Compute&& compute) const {
    if (const T* value = get()) return *value;
    Node* made = new Node{compute()};
    Node* expected = nullptr;
    if (node_.compare_exchange_strong(expected, made, std::memory_order_acq_rel, std::memory_order_acquire))
      return made->value;
    delete made;  // lost the race: expected holds the winner's node
    return expected->value;
  }

 private:
  struct Node {
    T value;
    std::atomic<long> references{1};
  };

  Node* acquire_node() const {
    Node* node = node_.load(std::memory_order_acquire);
    if (node != nullptr) node->references.fetch_add(1, std::memory_order_relaxed);
    return node;
  }
  static void release(Node* node) {
    if (node != nullptr && node->references.fetch_sub(1, std::memory_order_acq_rel) == 1) delete node;
  }

  mutable std::atomic<Node*> node_{nullptr};  // null, or a node whose value never changes
};

}  // namespace apollonius
