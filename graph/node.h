#pragma once
// The contract between the graph framework and a node implementation (MediaPipe-style):
// a node declares its typed input and output ports separately from its processing, and
// processes one Envelope at a time, emitting results on its output ports.
//
// A message payload is any struct with `static constexpr const char* kMessageName`;
// ports are typed by that name and checked when the graph is built.

#include <any>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeindex>
#include <vector>

#include "engine/refine/refine.h"
#include "graph/params.h"

namespace papercraft {

struct ModelRun;

/// A message type: its name (as shown to users and in errors) and its C++ type.
struct MessageType {
  std::string name;
  std::type_index type = typeid(void);

  template <class T>
  static MessageType of() {
    return {T::kMessageName, typeid(T)};
  }
};

/// One message in flight: the model it belongs to and a payload (shared_ptr<const T>).
/// A gathering input receives a `Gathered` payload (all messages of one model).
struct Envelope {
  std::shared_ptr<ModelRun> model;
  std::any payload;

  template <class T>
  const T& get() const {
    return *std::any_cast<std::shared_ptr<const T>>(payload);
  }
  template <class T>
  std::shared_ptr<const T> get_shared() const {
    return std::any_cast<std::shared_ptr<const T>>(payload);
  }
};

/// Everything one model sent to a gathering input, in arrival order.
struct Gathered {
  static constexpr const char* kMessageName = "Gathered";
  std::vector<std::any> items;

  template <class T>
  std::vector<std::shared_ptr<const T>> as() const {
    std::vector<std::shared_ptr<const T>> out;
    out.reserve(items.size());
    for (const auto& item : items) out.push_back(std::any_cast<std::shared_ptr<const T>>(item));
    return out;
  }
};

/// Sends payloads to a node's output ports, named as the node's spec declares them ("out",
/// "accept", ...); installed by the framework for each call. Emitting on a port the spec does
/// not declare, or a payload of another type, is a framework bug (InternalError).
class Emitter {
 public:
  virtual ~Emitter() = default;
  template <class T>
  void emit(std::string_view port, std::shared_ptr<const T> payload) {
    emit_any(port, typeid(T), std::any(std::move(payload)));
  }
  template <class T>
  void emit(std::string_view port, T&& value) {
    emit<std::decay_t<T>>(port, std::make_shared<const std::decay_t<T>>(std::forward<T>(value)));
  }

 protected:
  virtual void emit_any(std::string_view port, std::type_index type, std::any payload) = 0;
};

/// The processing of one node instance. `process` may be called concurrently (up to the
/// node's concurrency) and must not block on other nodes.
class NodeBody {
 public:
  virtual ~NodeBody() = default;
  virtual void process(const Envelope& input, Emitter& output) = 0;
};

struct OutputPort {
  std::string name;  // "out" for single-output nodes; "accept"/"reject" etc.
  MessageType type;
};

/// What a node may know of the pipeline it is built into, besides its own parameters.
struct NodeContext {
  /// The refinement as this pipeline configures it: every node that contributes to it
  /// (NodeSpec::refinement: the select, ruled, hausdorff and cut stages) has written its
  /// parameters in, defaults stand for the stages the config lacks. It holds no tolerance:
  /// each model brings its own (at_tolerance). Nodes that run the refinement themselves
  /// (segment estimates) use it, so they refine as the graph does.
  RefineOptions refine;
};

/// A registered implementation: its contract, parameters and factory. Written with
/// designated initialisers:
///   registry.add({.name = "unfold.sequential", .summary = "...",
///                 .input = MessageType::of<AcceptedStrip>(),
///                 .outputs = {{"out", MessageType::of<UnfoldedStrip>()}},
///                 .params = table.specs(), .create = ...});
struct NodeSpec {
  std::string name;     // dotted: "hausdorff.bounded"
  std::string summary;  // one line for `papercraft nodes`
  MessageType input;
  bool gathers = false;  // input receives all messages of a model at once (Gathered)
  std::vector<OutputPort> outputs = {};
  std::vector<ParamSpec> params = {};
  /// For a stage of the refinement: writes this node's parameters into the engine's options
  /// (applied in config order to build NodeContext::refine).
  std::function<void(const Params&, RefineOptions&)> refinement = {};
  std::function<std::unique_ptr<NodeBody>(const Params&, const NodeContext&)> create = {};

  std::string stage() const { return name.substr(0, name.find('.')); }
};

/// Convenience: a NodeBody from a lambda `void(const Envelope&, Emitter&)`.
template <class Fn>
std::unique_ptr<NodeBody> make_body(Fn fn) {
  struct LambdaBody : NodeBody {
    explicit LambdaBody(Fn f) : fn_(std::move(f)) {}
    void process(const Envelope& input, Emitter& output) override { fn_(input, output); }
    Fn fn_;
  };
  return std::make_unique<LambdaBody>(std::move(fn));
}

/// Completes the spec of a stage of the refinement loop (select, ruled, hausdorff, cut):
/// `configure` writes the node's parameters into the engine's options (NodeSpec::refinement),
/// and `body` makes the node's processing from the pipeline's options with them applied, so
/// the node runs the very step the engine runs for the segmentation's estimates.
inline NodeSpec refinement_stage(
    NodeSpec spec, std::function<void(const Params&, RefineOptions&)> configure,
    std::function<std::unique_ptr<NodeBody>(const RefineOptions&)> body) {
  spec.refinement = configure;
  spec.create = [configure, body](const Params& params, const NodeContext& context) {
    RefineOptions refine = context.refine;
    configure(params, refine);
    return body(refine);
  };
  return spec;
}

}  // namespace papercraft
