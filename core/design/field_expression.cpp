#include "core/design/field_expression.h"

#include <muParser.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace tfd::core {
namespace {

/// One muParser instance per component, bound to the point (x, y, z). Not thread-safe: each
/// worker builds its own.
class ExpressionEvaluator {
 public:
  explicit ExpressionEvaluator(const TensorExpressions& expressions) {
    for (int c = 0; c < 6; ++c) {
      auto& parser = parsers_[c];
      parser.DefineVar("x", &point_[0]);
      parser.DefineVar("y", &point_[1]);
      parser.DefineVar("z", &point_[2]);
      parser.DefineConst("pi", M_PI);
      try {
        parser.SetExpr(expressions.components[c]);
        parser.Eval();  // parses, and reports undefined variables
      } catch (const mu::Parser::exception_type& e) {
        std::ostringstream message;
        message << "component \"" << tensorComponentNames()[c] << "\" (\""
                << expressions.components[c] << "\"): " << e.GetMsg();
        throw Error(message.str());
      }
    }
  }

  Tensor evaluate(const Vec3& p) {
    point_[0] = p.x(), point_[1] = p.y(), point_[2] = p.z();
    std::array<double, 6> c;
    for (int i = 0; i < 6; ++i) c[i] = parsers_[i].Eval();
    return Tensor::fromComponents(c);
  }

 private:
  std::array<mu::Parser, 6> parsers_;
  double point_[3] = {0, 0, 0};
};

}  // namespace

const std::array<const char*, 6>& tensorComponentNames() {
  static const std::array<const char*, 6> names = {"xx", "yy", "zz", "xy", "yz", "xz"};
  return names;
}

void checkExpressions(const TensorExpressions& expressions) {
  ExpressionEvaluator evaluator(expressions);
}

TensorField evaluateFieldExpression(std::shared_ptr<const TetMesh> mesh,
                                    const TensorExpressions& expressions,
                                    const Progress& progress) {
  checkExpressions(expressions);
  const auto& positions = mesh->positions();
  std::vector<Tensor> values(positions.size());
  std::atomic<long> firstBad{-1};
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, positions.size(), 4096),
      [&](const tbb::blocked_range<std::size_t>& range) {
        if (progress.cancelled()) return;
        ExpressionEvaluator evaluator(expressions);
        for (std::size_t v = range.begin(); v != range.end(); ++v) {
          const Tensor t = evaluator.evaluate(positions[v]);
          if (!std::isfinite(t.norm())) {
            // Keep the smallest bad vertex id: the message must not depend on
            // thread scheduling.
            long seen = firstBad.load();
            while ((seen < 0 || long(v) < seen) && !firstBad.compare_exchange_weak(seen, long(v))) {
            }
          }
          values[v] = t.deviator();
        }
      });
  progress.throwIfCancelled();
  if (const long v = firstBad.load(); v >= 0) {
    const Vec3& p = positions[v];
    std::ostringstream message;
    message << "the expressions give a non-finite tensor at (" << p.x() << ", " << p.y() << ", "
            << p.z() << ")";
    throw Error(message.str());
  }
  return TensorField(std::move(mesh), std::move(values));
}

}  // namespace tfd::core
