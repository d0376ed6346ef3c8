#pragma once
// Small test-only node implementations (not part of the product) for builder tests. The
// sinks tally what they see per model index (`tally`), since the product's model record has
// no fields for test items.

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "graph/pipeline.h"
#include "graph/registry.h"

namespace papercraft::testing {

struct Item {
  static constexpr const char* kMessageName = "Item";
  int value = 0;
};

struct Summary {
  static constexpr const char* kMessageName = "Summary";
  long count = 0;
  long sum = 0;
};

/// Counts how often the sink saw any model, to prove completion fires once.
inline std::atomic<int> sink_calls{0};

/// Values the sinks add up per model index and key ("items", "sum", "count", "sink_calls").
class Tally {
 public:
  void add(int model, const std::string& key, long value) {
    std::lock_guard lock(mutex_);
    values_[model][key] += value;
  }
  /// 0 when nothing was added.
  long get(int model, const std::string& key) const {
    std::lock_guard lock(mutex_);
    auto it = values_.find(model);
    if (it == values_.end()) return 0;
    auto value = it->second.find(key);
    return value == it->second.end() ? 0 : value->second;
  }
  bool has(int model, const std::string& key) const {
    std::lock_guard lock(mutex_);
    auto it = values_.find(model);
    return it != values_.end() && it->second.count(key) > 0;
  }
  void clear() {
    std::lock_guard lock(mutex_);
    values_.clear();
  }

 private:
  mutable std::mutex mutex_;
  std::map<int, std::map<std::string, long>> values_;
};

inline Tally tally;

inline NodeSpec test_spec(std::string name, std::string summary, MessageType input,
                          std::vector<OutputPort> outputs,
                          std::function<std::unique_ptr<NodeBody>(const Params&)> create,
                          std::vector<ParamSpec> params = {}, bool gathers = false) {
  return {.name = std::move(name),
          .summary = std::move(summary),
          .input = std::move(input),
          .gathers = gathers,
          .outputs = std::move(outputs),
          .params = std::move(params),
          .create = [create](const Params& p, const NodeContext&) { return create(p); }};
}

inline Registry test_registry() {
  Registry r;
  r.add(test_spec(
      "test.source", "emits `count` items 1..count", MessageType::of<Job>(),
      {{"out", MessageType::of<Item>()}},
      [](const Params& p) {
        const long count = p.integer("count");
        const long fail_every = p.integer("fail_every");
        return make_body([count, fail_every](const Envelope& in, Emitter& out) {
          if (fail_every > 0 && in.model->index % fail_every == 1) {
            throw std::runtime_error("bad model " + std::to_string(in.model->index));
          }
          for (int i = 1; i <= count; ++i) out.emit("out", Item{i});
        });
      },
      {{"count", ParamType::Integer, "3", "items per model"},
       {"fail_every", ParamType::Integer, "0", "throw for model index % fail_every == 1"}}));
  r.add(test_spec("test.double", "doubles the value", MessageType::of<Item>(),
                  {{"out", MessageType::of<Item>()}}, [](const Params&) {
                    return make_body([](const Envelope& in, Emitter& out) {
                      out.emit("out", Item{2 * in.get<Item>().value});
                    });
                  }));
  r.add(test_spec(
      "test.loop", "splits an item in two until it reaches `limit`", MessageType::of<Item>(),
      {{"done", MessageType::of<Item>()}, {"again", MessageType::of<Item>()}},
      [](const Params& p) {
        const long limit = p.integer("limit");
        return make_body([limit](const Envelope& in, Emitter& out) {
          const int v = in.get<Item>().value;
          if (v >= limit) {
            out.emit("done", Item{v});
          } else {
            out.emit("again", Item{v + 1});
            out.emit("again", Item{v + 1});
          }
        });
      },
      {{"limit", ParamType::Integer, "16", "values >= limit leave the loop"}}));
  r.add(test_spec("test.even", "routes even values to 'even', odd to 'odd'",
                  MessageType::of<Item>(),
                  {{"even", MessageType::of<Item>()}, {"odd", MessageType::of<Item>()}},
                  [](const Params&) {
                    return make_body([](const Envelope& in, Emitter& out) {
                      const int v = in.get<Item>().value;
                      out.emit(v % 2 == 0 ? "even" : "odd", Item{v});
                    });
                  }));
  r.add(test_spec("test.mod3", "routes values by remainder: 'zero', 'one', 'two'",
                  MessageType::of<Item>(),
                  {{"zero", MessageType::of<Item>()},
                   {"one", MessageType::of<Item>()},
                   {"two", MessageType::of<Item>()}},
                  [](const Params&) {
                    return make_body([](const Envelope& in, Emitter& out) {
                      static const char* const kPorts[] = {"zero", "one", "two"};
                      const int v = in.get<Item>().value;
                      out.emit(kPorts[v % 3], Item{v});
                    });
                  }));
  r.add(test_spec("test.rogue", "emits on a port it does not declare (a framework bug)",
                  MessageType::of<Item>(), {{"out", MessageType::of<Item>()}},
                  [](const Params&) {
                    return make_body([](const Envelope& in, Emitter& out) {
                      out.emit("undeclared", Item{in.get<Item>().value});
                    });
                  }));
  r.add(test_spec(
      "test.collect", "sums all items of a model", MessageType::of<Item>(),
      {{"out", MessageType::of<Summary>()}},
      [](const Params&) {
        return make_body([](const Envelope& in, Emitter& out) {
          Summary s;
          for (const auto& item : in.get<Gathered>().as<Item>()) {
            s.count++;
            s.sum += item->value;
          }
          out.emit("out", s);
        });
      },
      {}, /*gathers=*/true));
  r.add(test_spec("test.sink", "tallies the summary", MessageType::of<Summary>(), {},
                  [](const Params&) {
                    return make_body([](const Envelope& in, Emitter&) {
                      sink_calls.fetch_add(1);
                      const int model = in.model->index;
                      tally.add(model, "sink_calls", 1);
                      tally.add(model, "count", in.get<Summary>().count);
                      tally.add(model, "sum", in.get<Summary>().sum);
                    });
                  }));
  r.add(test_spec("test.sleep", "passes each item on after `milliseconds`", MessageType::of<Item>(),
                  {{"out", MessageType::of<Item>()}},
                  [](const Params& p) {
                    const long milliseconds = p.integer("milliseconds");
                    return make_body([milliseconds](const Envelope& in, Emitter& out) {
                      std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
                      out.emit("out", Item{in.get<Item>().value});
                    });
                  },
                  {{"milliseconds", ParamType::Integer, "10", "how long each item takes"}}));
  r.add(test_spec("test.item_sink", "tallies item values", MessageType::of<Item>(), {},
                  [](const Params&) {
                    return make_body([](const Envelope& in, Emitter&) {
                      tally.add(in.model->index, "items", 1);
                      tally.add(in.model->index, "sum", in.get<Item>().value);
                    });
                  }));
  return r;
}

}  // namespace papercraft::testing
