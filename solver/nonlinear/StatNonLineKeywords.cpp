// StatNonLineKeywords: the support table of STAT_NON_LINE's keywords and the refusal walk.

#include "solver/nonlinear/StatNonLineKeywords.hpp"

#include "interpreter/Diagnostics.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

constexpr KeywordSupport I = KeywordSupport::Implemented;
constexpr KeywordSupport N = KeywordSupport::NoEffect;
constexpr KeywordSupport R = KeywordSupport::Refused;

// A refused keyword whose value equal to `accepted` (its default) is accepted.
struct Entry {
  const char* path;
  KeywordSupport support;
  const char* note;
  const char* accepted = nullptr;
};

const Entry kEntries[] = {
    {"RESULTAT", I, "with reuse=: the result continued"},
    {"MODELE", I, ""},
    {"CHAM_MATER", I, ""},
    {"CARA_ELEM", I, "discrete springs (DIS_T, 2D_DIS_T)"},
    {"EXCIT", I, "CHARGE, FONC_MULT; TYPE_CHARGE other than FIXE_CSTE refused by the load reader"},
    {"CONTACT", I, "see DEFI_CONTACT"},
    {"COMPORTEMENT", I, ""},
    {"COMPORTEMENT/TOUT", I, ""},
    {"COMPORTEMENT/GROUP_MA", I, ""},
    {"COMPORTEMENT/RELATION", I, "ELAS, VMIS_ISOT_LINE (others refused by the behaviour reader)"},
    {"COMPORTEMENT/DEFORMATION", I, "PETIT (others refused)"},
    {"COMPORTEMENT/RESI_INTE", N, "the radial return of VMIS_ISOT_LINE is exact"},
    {"COMPORTEMENT/ITER_INTE_MAXI", N, "the radial return of VMIS_ISOT_LINE is exact"},
    {"COMPORTEMENT/ALGO_INTE", N, "the radial return of VMIS_ISOT_LINE is exact (ANALYTIQUE)"},
    {"COMPORTEMENT/RESI_CPLAN_RELA", N, "plane stress iterations converge to round-off"},
    {"COMPORTEMENT/ITER_CPLAN_MAXI", N, "plane stress iterations converge to round-off"},
    {"COMPORTEMENT/RESI_CPLAN_MAXI", R, "absolute tolerance of the plane stress iterations"},
    {"COMPORTEMENT/ALGO_CPLAN", R, "choice of the plane stress algorithm", "ANALYTIQUE"},
    {"COMPORTEMENT/ITER_INTE_PAS", R, "sub-stepping of the local integration", "0"},
    {"COMPORTEMENT/PARM_THETA", R, "theta scheme of the local integration", "1.0"},
    {"COMPORTEMENT/TYPE_MATR_TANG", R, "perturbation / secant tangents"},
    {"COMPORTEMENT/VALE_PERT_RELA", R, "perturbation tangent"},
    {"COMPORTEMENT/SEUIL", R, "secant tangent threshold"},
    {"COMPORTEMENT/AMPLITUDE", R, "secant tangent"},
    {"COMPORTEMENT/TAUX_RETOUR", R, "secant tangent"},
    {"COMPORTEMENT/RESI_RADI_RELA", R, "radial loading check"},
    {"COMPORTEMENT/SYME_MATR_TANG", R, "symmetrised tangent", "OUI"},
    {"COMPORTEMENT/RIGI_GEOM", R, "geometric stiffness"},
    {"COMPORTEMENT/RELATION_KIT", R, "behaviour kits"},
    {"COMPORTEMENT/COMPOR", R, "multifibre behaviours"},
    {"COMPORTEMENT/COMPOR_MFRONT", R, "MFront behaviours"},
    {"COMPORTEMENT/LIBRAIRIE", R, "external behaviours"},
    {"COMPORTEMENT/NOM_ROUTINE", R, "external behaviours"},
    {"COMPORTEMENT/NB_VARI", R, "external behaviours"},
    {"COMPORTEMENT/POST_ITER", R, "post-iteration treatments"},
    {"COMPORTEMENT/POST_INCR", R, "post-increment treatments"},
    {"COMPORTEMENT/REGU_VISC", R, "viscous regularisation", "NON"},
    {"COMPORTEMENT/VERI_BORNE", R, "bound checks"},
    {"ETAT_INIT", I, "EVOL_NOLI with INST / NUME_ORDRE (CRITERE, PRECISION)"},
    {"ETAT_INIT/EVOL_NOLI", I, ""},
    {"ETAT_INIT/NUME_ORDRE", I, ""},
    {"ETAT_INIT/INST", I, ""},
    {"ETAT_INIT/CRITERE", I, ""},
    {"ETAT_INIT/PRECISION", I, ""},
    {"ETAT_INIT/NUME_DIDI", R, "ETAT_INIT/NUME_DIDI"},
    {"ETAT_INIT/DEPL", R, "initial fields given one by one (give EVOL_NOLI)"},
    {"ETAT_INIT/SIGM", R, "initial fields given one by one (give EVOL_NOLI)"},
    {"ETAT_INIT/VARI", R, "initial fields given one by one (give EVOL_NOLI)"},
    {"ETAT_INIT/STRX", R, "structural element fields"},
    {"INCREMENT", I, ""},
    {"INCREMENT/LIST_INST", I, ""},
    {"INCREMENT/INST_INIT", I, ""},
    {"INCREMENT/INST_FIN", I, ""},
    {"INCREMENT/NUME_INST_INIT", I, ""},
    {"INCREMENT/NUME_INST_FIN", I, ""},
    {"INCREMENT/CRITERE", I, ""},
    {"INCREMENT/PRECISION", I, ""},
    {"METHODE", R, "METHODE other than NEWTON (IMPLEX, NEWTON_KRYLOV)", "NEWTON"},
    {"NEWTON", I, ""},
    {"NEWTON/MATRICE", I, "TANGENTE, ELASTIQUE"},
    {"NEWTON/REAC_ITER", I, ""},
    {"NEWTON/REAC_INCR", I, ""},
    {"NEWTON/PREDICTION", I, "TANGENTE, ELASTIQUE, EXTRAPOLE, DEPL_CALCULE"},
    {"NEWTON/EVOL_NOLI", I, "for PREDICTION='DEPL_CALCULE'"},
    {"NEWTON/PAS_MINI_ELAS", R, "NEWTON/PAS_MINI_ELAS (elastic matrix below a step length)"},
    {"NEWTON/REAC_ITER_ELAS", R, "NEWTON/REAC_ITER_ELAS", "0"},
    {"NEWTON/MATR_RIGI_SYME", I, "'OUI': the tangent's symmetric part (K + K^T) / 2, factorised symmetric"},
    {"RECH_LINEAIRE", I, "METHODE='CORDE'"},
    {"RECH_LINEAIRE/METHODE", I, "CORDE (MIXTE, PILOTAGE refused by name)"},
    {"RECH_LINEAIRE/RESI_LINE_RELA", I, ""},
    {"RECH_LINEAIRE/ITER_LINE_MAXI", I, ""},
    {"RECH_LINEAIRE/RHO_MIN", I, ""},
    {"RECH_LINEAIRE/RHO_MAX", I, ""},
    {"RECH_LINEAIRE/RHO_EXCL", I, ""},
    {"PILOTAGE", R, "PILOTAGE (load control)"},
    {"CONVERGENCE", I, ""},
    {"CONVERGENCE/RESI_GLOB_RELA", I, ""},
    {"CONVERGENCE/RESI_GLOB_MAXI", I, ""},
    {"CONVERGENCE/ITER_GLOB_MAXI", I, ""},
    {"CONVERGENCE/ITER_GLOB_ELAS", I, "the iteration limit with MATRICE='ELASTIQUE'"},
    {"CONVERGENCE/ARRET", R, "CONVERGENCE/ARRET='NON' (accepting unconverged steps)", "OUI"},
    {"CONVERGENCE/VERIF", I, "TOUT: every criterion given holds; AU_MOINS_UN: one is enough"},
    {"CONVERGENCE/RESI_REFE_RELA", R, "CONVERGENCE/RESI_REFE_RELA (reference residuals)"},
    {"CONVERGENCE/RESI_COMP_RELA", R, "CONVERGENCE/RESI_COMP_RELA"},
    {"CONVERGENCE/SIGM_REFE", R, "reference residuals"},
    {"CONVERGENCE/EPSI_REFE", R, "reference residuals"},
    {"CONVERGENCE/FLUX_THER_REFE", R, "reference residuals"},
    {"CONVERGENCE/EFFORT_REFE", R, "reference residuals"},
    {"CONVERGENCE/MOMENT_REFE", R, "reference residuals"},
    {"CONVERGENCE/FLUX_HYD1_REFE", R, "reference residuals"},
    {"CONVERGENCE/FLUX_HYD2_REFE", R, "reference residuals"},
    {"CONVERGENCE/VARI_REFE", R, "reference residuals"},
    {"CONVERGENCE/DEPL_REFE", R, "reference residuals"},
    {"CONVERGENCE/LAGR_REFE", R, "reference residuals"},
    {"CONVERGENCE/PI_REFE", R, "reference residuals"},
    {"SOLVEUR", I,
     "read by the shared SOLVEUR reader (METHODE, RENUM, NPREC, PCENT_PIVOT, STOP_SINGULIER...)"},
    {"OBSERVATION", I, "rows of the result's table 'OBSERVATION' (RECU_TABLE)"},
    {"OBSERVATION/NOM_CHAM", I, "DEPL, CONT_NOEU, SIEF_ELGA, VARI_ELGA, EPSI_ELGA (others refused by name)"},
    {"OBSERVATION/NOM_CMP", I, ""},
    {"OBSERVATION/NOM_VARI", R, "OBSERVATION/NOM_VARI (internal variables by name: give NOM_CMP='V1'...)"},
    {"OBSERVATION/EVAL_CMP", R, "OBSERVATION/EVAL_CMP='FORMULE'", "VALE"},
    {"OBSERVATION/FORMULE", R, "OBSERVATION/FORMULE"},
    {"OBSERVATION/EVAL_CHAM", I, "VALE, MIN, MAX, MOY, MAXI_ABS, MINI_ABS"},
    {"OBSERVATION/EVAL_ELGA", I, "VALE (at POINT), MIN, MAX"},
    {"OBSERVATION/POINT", I, ""},
    {"OBSERVATION/SOUS_POINT", R, "OBSERVATION/SOUS_POINT (no cell of stella has sub-points)"},
    {"OBSERVATION/TOUT", I, ""},
    {"OBSERVATION/NOEUD", I, ""},
    {"OBSERVATION/GROUP_NO", I, ""},
    {"OBSERVATION/MAILLE", I, ""},
    {"OBSERVATION/GROUP_MA", I, ""},
    {"OBSERVATION/TITRE", I, "the NOM_OBSERVATION column"},
    {"OBSERVATION/OBSE_ETAT_INIT", I, ""},
    {"OBSERVATION/INST", I, ""},
    {"OBSERVATION/LIST_INST", I, ""},
    {"OBSERVATION/PAS_OBSE", I, ""},
    {"OBSERVATION/CRITERE", I, ""},
    {"OBSERVATION/PRECISION", I, ""},
    {"MESURE", I, "the table 'STAT' of the step times"},
    {"MESURE/TABLE", I, "'OUI': the table attached to the result (RECU_TABLE NOM_TABLE='STAT')"},
    {"MESURE/UNITE", I, "the table written to that unit"},
    {"SUIVI_DDL", I, "columns of the convergence table"},
    {"SUIVI_DDL/NOM_CHAM", I, "DEPL, SIEF_ELGA, VARI_ELGA, EPSI_ELGA (others refused by name)"},
    {"SUIVI_DDL/NOM_CMP", I, ""},
    {"SUIVI_DDL/NOM_VARI", R, "SUIVI_DDL/NOM_VARI (internal variables by name: give NOM_CMP='V1'...)"},
    {"SUIVI_DDL/EVAL_CMP", R, "SUIVI_DDL/EVAL_CMP='FORMULE'", "VALE"},
    {"SUIVI_DDL/FORMULE", R, "SUIVI_DDL/FORMULE"},
    {"SUIVI_DDL/EVAL_CHAM", I, "VALE, MIN, MAX, MOY, MAXI_ABS, MINI_ABS"},
    {"SUIVI_DDL/EVAL_ELGA", I, "VALE (at POINT), MIN, MAX"},
    {"SUIVI_DDL/POINT", I, ""},
    {"SUIVI_DDL/SOUS_POINT", R, "SUIVI_DDL/SOUS_POINT (no cell of stella has sub-points)"},
    {"SUIVI_DDL/TOUT", I, ""},
    {"SUIVI_DDL/NOEUD", I, ""},
    {"SUIVI_DDL/GROUP_NO", I, ""},
    {"SUIVI_DDL/MAILLE", I, ""},
    {"SUIVI_DDL/GROUP_MA", I, ""},
    {"SUIVI_DDL/TITRE", I, "the column title"},
    {"ARCHIVAGE", I, ""},
    {"ARCHIVAGE/PAS_ARCH", I, ""},
    {"ARCHIVAGE/LIST_INST", I, ""},
    {"ARCHIVAGE/INST", I, ""},
    {"ARCHIVAGE/CRITERE", I, ""},
    {"ARCHIVAGE/PRECISION", I, ""},
    {"ARCHIVAGE/CHAM_EXCLU", N, "RESI_NOEU and RESI_RELA_NOEU are never stored"},
    {"ENERGIE", R, "ENERGIE"},
    {"AFFICHAGE", I, ""},
    {"AFFICHAGE/INFO_RESIDU", I,
     "every table has the WHERE (MAXI) column (the node of the largest residual)"},
    {"AFFICHAGE/INFO_TEMPS", R, "AFFICHAGE/INFO_TEMPS='OUI'", "NON"},
    {"AFFICHAGE/UNITE", I, "the tables also written to that unit"},
    {"AFFICHAGE/PAS", I, "the table of every PAS-th step in the message file"},
    {"CRIT_STAB", R, "CRIT_STAB (buckling criterion)"},
    {"INFO", N, "the message file always has the convergence tables"},
    {"INFO_DBG", N, "debugging output of code_aster"},
    {"TITRE", N, "titles are not stored"},
};

struct Table {
  std::map<std::string, KeywordStatus> statuses;
  std::map<std::string, std::string> accepted;
};

const Table& table() {
  static const Table t = [] {
    Table out;
    for (const Entry& e : kEntries) {
      out.statuses[e.path] = {e.support, e.note};
      if (e.accepted != nullptr) {
        out.accepted[e.path] = e.accepted;
      }
    }
    return out;
  }();
  return t;
}

// Whether the user's value is the one the table accepts (text, or the same number).
bool isAcceptedValue(const SimpleKeyword& k, const std::string& accepted) {
  if (k.values.size() != 1) {
    return false;
  }
  const Value& v = k.values.front();
  if (v.isString()) {
    return v.asString() == accepted;
  }
  if (v.isNumber()) {
    return v.asReal() == std::stod(accepted);
  }
  return false;
}

void walk(const KeywordTree& tree, const std::string& prefix) {
  for (const SimpleKeyword& k : tree.simples()) {
    const std::string path = prefix + k.name;
    const KeywordStatus* s = statNonLineKeywordStatus(path);
    if (k.defaulted || s == nullptr || s->support != KeywordSupport::Refused) {
      continue;
    }
    const auto accepted = table().accepted.find(path);
    if (accepted != table().accepted.end() && isAcceptedValue(k, accepted->second)) {
      continue;
    }
    throw UserError(
        Diagnostic::fatal("SNL_1", fmt::format("STAT_NON_LINE {} is not implemented yet", path), k.location)
            .withNote(s->note));
  }
  for (const FactorKeyword& f : tree.factors()) {
    const std::string path = prefix + f.name;
    const KeywordStatus* s = statNonLineKeywordStatus(path);
    if (!f.defaulted && s != nullptr && s->support == KeywordSupport::Refused) {
      throw UserError(
          Diagnostic::fatal("SNL_1", fmt::format("STAT_NON_LINE {} is not implemented yet", path), f.location)
              .withNote(s->note));
    }
    for (const KeywordTree& occ : f.occurrences) {
      walk(occ, path + "/");
    }
  }
}

} // namespace

const std::map<std::string, KeywordStatus>& statNonLineKeywords() {
  return table().statuses;
}

const KeywordStatus* statNonLineKeywordStatus(const std::string& path) {
  const auto& s = table().statuses;
  std::string p = path;
  while (true) {
    if (auto it = s.find(p); it != s.end()) {
      return &it->second;
    }
    const auto slash = p.rfind('/');
    if (slash == std::string::npos) {
      return nullptr;
    }
    p.resize(slash);
    // A factor listed as implemented does not cover unlisted keywords inside it, except
    // SOLVEUR and EXCIT whose whole content their readers check.
    if (auto it = s.find(p); it != s.end()) {
      const bool covers = it->second.support == KeywordSupport::Refused || p == "SOLVEUR" || p == "EXCIT";
      return covers ? &it->second : nullptr;
    }
  }
}

void refuseUnsupportedKeywords(const KeywordTree& statNonLine) {
  walk(statNonLine, "");
}

} // namespace stella
