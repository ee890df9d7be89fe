// DEFI_FONCTION: a tabulated function of one parameter (VALE pairs, ABSCISSE/ORDONNEE, or
// VALE_PARA/VALE_FONC lists), with INTERPOL and PROL_GAUCHE/PROL_DROITE.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <numeric>

namespace stella {

namespace {

Extension extension(const std::string& text) {
  return text == "CONSTANT" ? Extension::Constant
                            : (text == "LINEAIRE" ? Extension::Linear : Extension::Excluded);
}

std::vector<double> listValues(const KeywordTree& kw, const std::string& name) {
  auto list = conceptData<RealList>(kw.conceptValue(name));
  STELLA_ASSERT(list != nullptr, name + " holds no list of reals");
  return list->values;
}

void readPoints(const KeywordTree& kw, std::vector<double>& x, std::vector<double>& y) {
  if (kw.has("VALE")) {
    std::vector<double> pairs = kw.reals("VALE");
    if (pairs.size() % 2 != 0) {
      throw UserError(msg::make("FUNCTION_2", {{"pairs_count", pairs.size()}}, kw.locationOf("VALE")));
    }
    for (std::size_t i = 0; i < pairs.size(); i += 2) {
      x.push_back(pairs[i]);
      y.push_back(pairs[i + 1]);
    }
  } else if (kw.has("ABSCISSE")) {
    x = kw.reals("ABSCISSE");
    y = kw.reals("ORDONNEE");
  } else if (kw.has("VALE_PARA")) {
    x = listValues(kw, "VALE_PARA");
    y = listValues(kw, "VALE_FONC");
  } else {
    const std::string which = kw.has("VALE_C") ? "VALE_C" : "NOEUD_PARA";
    throw UserError(msg::make("FUNCTION_3", {{"which", which}}, kw.locationOf(which)));
  }
  if (x.size() != y.size()) {
    throw UserError(msg::make("FUNCTION_2.2", {{"x_count", x.size()}, {"y_count", y.size()}}, kw.location()));
  }
}

void orderAbscissas(const KeywordTree& kw, std::vector<double>& x, std::vector<double>& y) {
  bool check = kw.text("VERIF") == "CROISSANT";
  if (check) {
    for (std::size_t i = 1; i < x.size(); ++i) {
      if (!(x[i] > x[i - 1])) {
        throw UserError(
            msg::make("FUNCTION_4", {{"i", i + 1}, {"x", x[i]}, {"x_2", x[i - 1]}}, kw.location()));
      }
    }
    return;
  }
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> xs;
  std::vector<double> ys;
  for (std::size_t i : order) {
    xs.push_back(x[i]);
    ys.push_back(y[i]);
  }
  x = std::move(xs);
  y = std::move(ys);
}

Value runDefiFonction(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  std::vector<double> x;
  std::vector<double> y;
  readPoints(kw, x, y);
  orderAbscissas(kw, x, y);
  std::vector<std::string> interpolation = kw.texts("INTERPOL");
  if (interpolation.empty()) {
    interpolation = {"LIN"};
  }
  bool logX = interpolation.front() == "LOG";
  bool logY = interpolation.back() == "LOG";
  auto positive = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double t) { return t > 0; });
  };
  if ((logX && !positive(x)) || (logY && !positive(y))) {
    throw UserError(msg::make("FUNCTION_5", {}, kw.locationOf("INTERPOL")));
  }
  auto f = std::make_shared<TabulatedFunction>(kw.text("NOM_PARA"), std::move(x), std::move(y));
  f->logX = logX;
  f->logY = logY;
  f->left = extension(kw.text("PROL_GAUCHE"));
  f->right = extension(kw.text("PROL_DROITE"));
  f->name = call.resultName;
  return call.makeConcept(f);
}

} // namespace

STELLA_OPERATOR("DEFI_FONCTION", runDefiFonction);

} // namespace stella
