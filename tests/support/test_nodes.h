#pragma once
// Small test-only node implementations (not part of the product) for builder tests.

#include <atomic>
#include <stdexcept>

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

/// Counts how often the sink saw each model (index -> count), to prove completion fires once.
inline std::atomic<int> sink_calls{0};

inline Registry test_registry() {
  Registry r;
  r.add({"test.source",
         "emits `count` items 1..count",
         MessageType::of<Job>(),
         false,
         {{"out", MessageType::of<Item>()}},
         {{"count", ParamType::Integer, "3", "items per model"},
          {"fail_every", ParamType::Integer, "0", "throw for model index % fail_every == 1"}},
         [](const Params& p) {
           const long count = p.integer("count");
           const long fail_every = p.integer("fail_every");
           return make_body([count, fail_every](const Envelope& in, Emitter& out) {
             if (fail_every > 0 && in.model->index % fail_every == 1) {
               throw std::runtime_error("bad model " + std::to_string(in.model->index));
             }
             for (int i = 1; i <= count; ++i) out.emit(0, Item{i});
           });
         }});
  r.add({"test.double",
         "doubles the value",
         MessageType::of<Item>(),
         false,
         {{"out", MessageType::of<Item>()}},
         {},
         [](const Params&) {
           return make_body([](const Envelope& in, Emitter& out) {
             out.emit(0, Item{2 * in.get<Item>().value});
           });
         }});
  r.add({"test.loop",
         "splits an item in two until it reaches `limit`",
         MessageType::of<Item>(),
         false,
         {{"done", MessageType::of<Item>()}, {"again", MessageType::of<Item>()}},
         {{"limit", ParamType::Integer, "16", "values >= limit leave the loop"}},
         [](const Params& p) {
           const long limit = p.integer("limit");
           return make_body([limit](const Envelope& in, Emitter& out) {
             const int v = in.get<Item>().value;
             if (v >= limit) {
               out.emit(0, Item{v});
             } else {
               out.emit(1, Item{v + 1});
               out.emit(1, Item{v + 1});
             }
           });
         }});
  r.add({"test.even",
         "routes even values to 'even', odd to 'odd'",
         MessageType::of<Item>(),
         false,
         {{"even", MessageType::of<Item>()}, {"odd", MessageType::of<Item>()}},
         {},
         [](const Params&) {
           return make_body([](const Envelope& in, Emitter& out) {
             const int v = in.get<Item>().value;
             out.emit(v % 2 == 0 ? 0 : 1, Item{v});
           });
         }});
  r.add({"test.collect",
         "sums all items of a model",
         MessageType::of<Item>(),
         true,
         {{"out", MessageType::of<Summary>()}},
         {},
         [](const Params&) {
           return make_body([](const Envelope& in, Emitter& out) {
             Summary s;
             for (const auto& item : in.get<Gathered>().as<Item>()) {
               s.count++;
               s.sum += item->value;
             }
             out.emit(0, s);
           });
         }});
  r.add({"test.sink",
         "records the summary in the model's results",
         MessageType::of<Summary>(),
         false,
         {},
         {},
         [](const Params&) {
           return make_body([](const Envelope& in, Emitter&) {
             sink_calls.fetch_add(1);
             in.model->add_result("sink_calls", 1);
             in.model->set_result("count", static_cast<double>(in.get<Summary>().count));
             in.model->set_result("sum", static_cast<double>(in.get<Summary>().sum));
           });
         }});
  r.add({"test.item_sink",
         "adds item values to the model's results",
         MessageType::of<Item>(),
         false,
         {},
         {},
         [](const Params&) {
           return make_body([](const Envelope& in, Emitter&) {
             in.model->add_result("items", 1);
             in.model->add_result("sum", in.get<Item>().value);
           });
         }});
  return r;
}

}  // namespace papercraft::testing
