#include "graph/pipeline.h"

#include <spdlog/spdlog.h>
#include <tbb/flow_graph.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <condition_variable>
#include <set>
#include <thread>
#include <typeinfo>

#include "core/errors.h"
#include "core/printable_utf8.h"
#include "graph/messages.h"

namespace papercraft {

namespace flow = tbb::flow;

namespace {

// A node body; its output ports are broadcast nodes (any number), edges leave from them.
using FlowNode = flow::function_node<Envelope>;
using PortNode = flow::broadcast_node<Envelope>;
using GatherNode = flow::multifunction_node<Envelope, std::tuple<Envelope>>;

RefineOptions refine_options_of(const PipelineConfig& config, const Registry& registry) {
  RefineOptions options;
  for (const auto& node : config.nodes) {
    const NodeSpec* spec = registry.find(node.impl);
    if (spec && spec->refinement) spec->refinement(node.params, options);
  }
  return options;
}

}  // namespace

std::vector<std::string> unique_model_names(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::string> names;
  std::map<std::string, int> used;
  for (const auto& input : inputs) {
    std::string stem = input.stem().string();
    if (stem.empty()) stem = "model";
    const int count = ++used[stem];
    names.push_back(count == 1 ? stem : stem + "-" + std::to_string(count));
  }
  return names;
}

Pipeline::Pipeline(PipelineConfig config, const Registry& registry)
    : config_(std::move(config)), registry_(registry) {}

Pipeline::~Pipeline() = default;

RefineOptions Pipeline::refine_options() const {
  return refine_options_of(config_, registry_);
}

std::vector<std::string> Pipeline::node_names() const {
  std::vector<std::string> names;
  for (const auto& n : config_.nodes) names.push_back(n.name);
  return names;
}

std::vector<NodeTiming> Pipeline::timings(const ModelRun& run) const {
  std::vector<NodeTiming> out;
  for (std::size_t i = 0; i < config_.nodes.size(); ++i) {
    out.push_back({config_.nodes[i].name, config_.nodes[i].impl, run.node_stats[i].calls.load(),
                   run.node_stats[i].nanoseconds.load() * 1e-9});
  }
  return out;
}

namespace {

// The state of one run() call: the flow graph, the job feed and the results.
class Execution {
 public:
  Execution(const PipelineConfig& config, const Registry& registry,
            const std::vector<std::filesystem::path>& inputs,
            std::shared_ptr<const RunSettings> settings, const PipelineOptions& options)
      : config_(config),
        inputs_(inputs),
        names_(options.names.empty() ? unique_model_names(inputs) : options.names),
        settings_(std::move(settings)),
        options_(options),
        results_(inputs.size()) {
    const std::size_t n = config.nodes.size();
    specs_.resize(n);
    gather_of_node_.assign(n, -1);
    successors_.resize(n);
    NodeContext context;
    context.refine = refine_options_of(config, registry);
    for (std::size_t i = 0; i < n; ++i) {
      specs_[i] = registry.find(config.nodes[i].impl);
      bodies_.push_back(
          std::shared_ptr<NodeBody>(specs_[i]->create(config.nodes[i].params, context)));
      successors_[i].assign(specs_[i]->outputs.size(), 0);
    }
    for (const auto& e : config.edges) successors_[e.from][e.port]++;
  }

  std::vector<ModelResult> run() {
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
      results_[i].name = names_[i];
      results_[i].input = inputs_[i];
      results_[i].error = "not started: the run was stopped";
    }
    const int threads = options_.threads > 0 ? options_.threads : tbb::info::default_concurrency();
    max_in_flight_ =
        options_.max_models_in_flight > 0 ? options_.max_models_in_flight : 2 * threads;
    tbb::task_arena arena(threads);
    std::thread ticker;
    if (options_.on_progress) ticker = std::thread([this] { progress_loop(); });
    arena.execute([&] {
      flow::graph graph;
      build(graph);
      const std::size_t first = std::min<std::size_t>(max_in_flight_, inputs_.size());
      for (std::size_t i = 0; i < first; ++i) start_next();
      graph.wait_for_all();
      // Nodes refer to their graph: destroy them while it is alive.
      gathers_.clear();
      ports_.clear();
      nodes_.clear();
    });
    {
      std::lock_guard lock(progress_mutex_);
      stop_progress_ = true;
    }
    progress_cv_.notify_all();
    if (ticker.joinable()) ticker.join();
    return std::move(results_);
  }

 private:
  void build(flow::graph& graph) {
    const std::size_t n = config_.nodes.size();
    for (std::size_t i = 0; i < n; ++i) {
      const int concurrency = config_.nodes[i].concurrency;
      const std::size_t limit =
          concurrency == 0 ? std::size_t{flow::unlimited} : static_cast<std::size_t>(concurrency);
      nodes_.push_back(std::make_unique<FlowNode>(graph, limit, [this, i](const Envelope& in) {
        run_node(static_cast<int>(i), in);
        return flow::continue_msg();
      }));
      ports_.emplace_back();
      for (std::size_t p = 0; p < specs_[i]->outputs.size(); ++p) {
        ports_.back().push_back(std::make_unique<PortNode>(graph));
      }
      if (specs_[i]->gathers) {
        const int g = static_cast<int>(gathers_.size());
        gather_of_node_[i] = g;
        gathers_.push_back(std::make_unique<GatherNode>(
            graph, flow::unlimited,
            [this, g](const Envelope& in, GatherNode::output_ports_type& ports) {
              run_gather(g, in, ports);
            }));
        flow::make_edge(flow::output_port<0>(*gathers_.back()), *nodes_[i]);
      }
    }
    // Gathers fire upstream first: order them by a topological order of the forward edges.
    std::vector<int> indegree(n, 0);
    for (const auto& e : config_.edges) {
      if (!e.back) indegree[e.to]++;
    }
    std::vector<int> ready;
    for (std::size_t i = 0; i < n; ++i) {
      if (indegree[i] == 0) ready.push_back(static_cast<int>(i));
    }
    while (!ready.empty()) {
      const int v = ready.back();
      ready.pop_back();
      if (gather_of_node_[v] >= 0) gather_order_.push_back(gather_of_node_[v]);
      for (const auto& e : config_.edges) {
        if (!e.back && e.from == v && --indegree[e.to] == 0) ready.push_back(e.to);
      }
    }
    for (const auto& e : config_.edges) {
      flow::receiver<Envelope>& target =
          gather_of_node_[e.to] >= 0
              ? static_cast<flow::receiver<Envelope>&>(*gathers_[gather_of_node_[e.to]])
              : static_cast<flow::receiver<Envelope>&>(*nodes_[e.to]);
      flow::make_edge(*ports_[e.from][e.port], target);
    }
  }

  class PortEmitter : public Emitter {
   public:
    PortEmitter(Execution& execution, int node, const Envelope& in)
        : execution_(execution), node_(node), in_(in) {}

   protected:
    void emit_any(std::string_view port, std::type_index type, std::any payload) override {
      const NodeSpec& spec = *execution_.specs_[node_];
      int index = -1;
      for (std::size_t p = 0; p < spec.outputs.size(); ++p) {
        if (spec.outputs[p].name == port) index = static_cast<int>(p);
      }
      if (index < 0) {
        throw InternalError(spec.name + " emitted on port '" + std::string(port) +
                            "' which it does not declare");
      }
      if (type != spec.outputs[index].type.type) {
        throw InternalError(spec.name + " emitted a message that is not " +
                            spec.outputs[index].type.name + " on port '" +
                            spec.outputs[index].name + "'");
      }
      if (node_ == execution_.config_.entry && type == typeid(Model)) {
        in_.model->set_input(std::any_cast<std::shared_ptr<const Model>>(payload)->summary);
      }
      const int successors = execution_.successors_[node_][index];
      if (successors == 0) return;  // unconnected port: dropped
      in_.model->in_flight.fetch_add(successors);
      execution_.ports_[node_][index]->try_put(Envelope{in_.model, std::move(payload)});
    }

   private:
    Execution& execution_;
    const int node_;
    const Envelope& in_;
  };

  void run_node(int index, const Envelope& in) {
    ModelRun& model = *in.model;
    if (options_.abandon.stop_requested()) model.abandon();
    if (!model.failed()) {
      model.stage.store(index);
      const auto start = std::chrono::steady_clock::now();
      const std::string& node = config_.nodes[index].name;
      try {
        PortEmitter emitter(*this, index, in);
        bodies_[index]->process(in, emitter);
      } catch (const std::invalid_argument& e) {
        model.fail(node, e.what());  // the input's fault (InvalidInputException is one)
      } catch (const std::logic_error& e) {
        model.fail(node, e.what(), /*internal=*/true);  // InternalError, out_of_range, ...
      } catch (const std::bad_cast& e) {
        model.fail(node, e.what(), /*internal=*/true);  // a payload of the wrong type
      } catch (const std::exception& e) {
        model.fail(node, e.what());
      } catch (...) {
        model.fail(node, "unknown exception", /*internal=*/true);
      }
      const auto elapsed = std::chrono::steady_clock::now() - start;
      model.node_stats[index].calls.fetch_add(1);
      model.node_stats[index].nanoseconds.fetch_add(
          std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed).count());
    }
    release(in.model);
  }

  void run_gather(int g, const Envelope& in, GatherNode::output_ports_type& ports) {
    ModelRun& model = *in.model;
    if (in.payload.has_value()) {
      std::lock_guard lock(model.gather_mutex);
      model.gathered[g].push_back(in.payload);
    } else if (!model.failed()) {
      auto batch = std::make_shared<Gathered>();
      {
        std::lock_guard lock(model.gather_mutex);
        batch->items = std::move(model.gathered[g]);
        model.gathered.erase(g);
      }
      model.in_flight.fetch_add(1);
      std::get<0>(ports).try_put(Envelope{in.model, std::shared_ptr<const Gathered>(batch)});
    }
    release(in.model);
  }

  void release(const std::shared_ptr<ModelRun>& model) {
    if (model->in_flight.fetch_sub(1) != 1) return;
    // Nothing of this model is left in the graph: fire the next gather or finish.
    if (options_.abandon.stop_requested()) model->abandon();
    if (!model->failed()) {
      for (const int g : gather_order_) {
        bool fire = false;
        {
          std::lock_guard lock(model->gather_mutex);
          if (model->gather_flushed.size() < gathers_.size()) {
            model->gather_flushed.resize(gathers_.size(), false);
          }
          if (!model->gather_flushed[g]) {
            model->gather_flushed[g] = true;
            fire = true;
          }
        }
        if (fire) {
          model->in_flight.fetch_add(1);
          gathers_[g]->try_put(Envelope{model, {}});
          return;
        }
      }
    }
    finish(model);
  }

  void start_next() {
    if (options_.stop_starting.stop_requested()) return;
    const std::size_t index = next_input_.fetch_add(1);
    if (index >= inputs_.size()) return;
    auto model = std::make_shared<ModelRun>(static_cast<int>(index), inputs_[index], names_[index],
                                            settings_, config_.nodes.size());
    results_[index].started = true;
    results_[index].queue_seconds =
        std::chrono::duration<double>(model->started - run_started_).count();
    {
      std::lock_guard lock(active_mutex_);
      active_.insert(model.get());
    }
    started_.fetch_add(1);
    for (const auto& node : config_.nodes) model->node_labels.emplace_back(node.name, node.impl);
    if (options_.on_model_started) options_.on_model_started(*model);
    model->in_flight.store(1);
    if (!settings_->keep_in_memory) {
      std::error_code ec;  // the staging folder of a run that was killed
      std::filesystem::remove_all(model->output_dir(), ec);
    }
    nodes_[config_.entry]->try_put(Envelope{
        model, std::make_shared<const Job>(Job{
                   inputs_[index], options_.meshes.empty() ? nullptr : options_.meshes[index]})});
  }

  // The staging folder becomes the model's folder whole (success) or goes away (failure).
  static void publish(ModelRun& model) {
    if (model.settings->keep_in_memory) return;  // no folder: the files are in the ModelRun
    const std::filesystem::path staging = model.output_dir(), final_dir = model.final_dir();
    std::error_code ec;
    if (model.failed() || model.abandoned()) {
      std::filesystem::remove_all(staging, ec);
      return;
    }
    if (!std::filesystem::exists(staging, ec)) return;  // a pipeline that writes nothing
    std::filesystem::path old;
    if (std::filesystem::exists(final_dir, ec)) {
      old = model.settings->output_dir / ("." + model.name + ".old-" + std::to_string(::getpid()));
      std::filesystem::remove_all(old, ec);
      std::filesystem::rename(final_dir, old, ec);
      if (ec) {
        model.fail("export",
                   "cannot replace " + printable_utf8(final_dir.string()) + ": " + ec.message());
        std::filesystem::remove_all(staging, ec);
        return;
      }
    }
    std::filesystem::rename(staging, final_dir, ec);
    if (ec) {
      model.fail("export", "cannot move the results into " + printable_utf8(final_dir.string()) +
                               ": " + ec.message());
      std::error_code ignored;
      if (!old.empty()) std::filesystem::rename(old, final_dir, ignored);
      std::filesystem::remove_all(staging, ignored);
      return;
    }
    if (!old.empty()) std::filesystem::remove_all(old, ec);
  }

  void finish(const std::shared_ptr<ModelRun>& model) {
    publish(*model);
    ModelResult& result = results_[model->index];
    result.ok = !model->failed();
    result.abandoned = model->abandoned();
    result.internal_error = model->internal_error();
    result.error = model->error();
    result.wall_seconds = model->seconds();
    for (const NodeStatistics& node : model->node_stats) {
      result.work_seconds += node.nanoseconds.load() * 1e-9;
    }
    result.record = model->record();
    if (result.ok) {
      spdlog::debug("{}: done in {:.3f} s", model->name, result.wall_seconds);
    } else if (!result.abandoned) {
      spdlog::error("{}: {}", printable_utf8(model->input_path.string()), result.error);
    }
    if (options_.on_model_done) options_.on_model_done(*model, result);
    {
      std::lock_guard lock(active_mutex_);
      active_.erase(model.get());
    }
    if (!result.ok) failed_.fetch_add(1);
    done_.fetch_add(1);
    start_next();
  }

  void progress_loop() {
    std::unique_lock lock(progress_mutex_);
    while (!progress_cv_.wait_for(lock, options_.progress_interval,
                                  [this] { return stop_progress_; })) {
      PipelineProgress progress;
      progress.total = inputs_.size();
      {
        std::lock_guard active_lock(active_mutex_);
        for (const ModelRun* m : active_) {
          const int stage = m->stage.load();
          progress.running.push_back(
              {m->name, stage >= 0 ? config_.nodes[stage].name : "queued", m->in_flight.load()});
        }
      }
      progress.started = started_.load();
      progress.done = done_.load();
      progress.failed = failed_.load();
      options_.on_progress(progress);
    }
  }

  const PipelineConfig& config_;
  const std::vector<std::filesystem::path>& inputs_;
  std::vector<std::string> names_;
  std::shared_ptr<const RunSettings> settings_;
  const PipelineOptions& options_;
  std::vector<ModelResult> results_;

  std::vector<const NodeSpec*> specs_;
  std::vector<std::shared_ptr<NodeBody>> bodies_;
  std::vector<std::unique_ptr<FlowNode>> nodes_;
  std::vector<std::vector<std::unique_ptr<PortNode>>> ports_;  // [node][output port]
  std::vector<std::vector<int>> successors_;                   // edges per [node][port]
  std::vector<std::unique_ptr<GatherNode>> gathers_;
  std::vector<int> gather_of_node_;
  std::vector<int> gather_order_;

  std::size_t max_in_flight_ = 1;
  std::atomic<std::size_t> next_input_{0};
  std::atomic<std::size_t> started_{0};
  std::atomic<std::size_t> done_{0};
  std::atomic<std::size_t> failed_{0};
  const std::chrono::steady_clock::time_point run_started_ = std::chrono::steady_clock::now();
  std::mutex active_mutex_;
  std::set<const ModelRun*> active_;
  std::mutex progress_mutex_;
  std::condition_variable progress_cv_;
  bool stop_progress_ = false;
};

}  // namespace

std::vector<ModelResult> Pipeline::run(const std::vector<std::filesystem::path>& inputs,
                                       std::shared_ptr<const RunSettings> settings,
                                       const PipelineOptions& options) {
  if (inputs.empty()) return {};
  if (!options.names.empty() && options.names.size() != inputs.size()) {
    throw std::invalid_argument("Pipeline::run: " + std::to_string(options.names.size()) +
                                " names for " + std::to_string(inputs.size()) + " inputs");
  }
  if (!options.meshes.empty() && options.meshes.size() != inputs.size()) {
    throw std::invalid_argument("Pipeline::run: " + std::to_string(options.meshes.size()) +
                                " meshes for " + std::to_string(inputs.size()) + " inputs");
  }
  Execution execution(config_, registry_, inputs, std::move(settings), options);
  return execution.run();
}

}  // namespace papercraft
