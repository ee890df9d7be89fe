// DEFI_CONSTANTE: a constant function (parameter TOUTPARA, as in code_aster), the value VALE
// for any value of its parameter; a one-point tabulated function extended as a constant on both
// sides. NOM_RESU and TITRE name it in the message file.

#include "solver/functions/RealFunction.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

Value runDefiConstante(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  const double value = kw.real("VALE");
  auto f =
      std::make_shared<TabulatedFunction>("TOUTPARA", std::vector<double>{0.0}, std::vector<double>{value});
  f->left = Extension::Constant;
  f->right = Extension::Constant;
  f->name = call.resultName;
  const std::string title = kw.textOr("TITRE", "");
  call.session.message() << fmt::format("  constant function {}: {} = {} for any value of TOUTPARA{}\n",
                                        call.resultName, kw.text("NOM_RESU"), Value(value).repr(),
                                        title.empty() ? "" : " (" + title + ")");
  return call.makeConcept(f);
}

} // namespace

STELLA_OPERATOR("DEFI_CONSTANTE", runDefiConstante);

} // namespace stella
