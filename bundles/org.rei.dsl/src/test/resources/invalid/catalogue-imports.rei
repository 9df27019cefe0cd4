// expect: 7:8 org.rei.dsl.catalogueImport | Cannot read catalogue 'missing.rei': no such file
// expect: 8:8 org.rei.dsl.catalogueImport | 'unknown-type.rei' is a test case: expected a catalogue file
// expect: 9:8 org.rei.dsl.catalogueInvalid | The catalogue '../catalogues/broken.rei' does not parse: line 3
// expect: 11:8 org.rei.dsl.duplicateName | Types Sofa, Scout of '../catalogues/copy.rei' are also declared in '../catalogues/office.rei'
// expect: 16:18 org.eclipse.xtext.diagnostics.Diagnostic.Linking | Unknown object type 'Armchair'
// expect: 12:8 org.rei.dsl.catalogueImport | A test case can not import itself
import "missing.rei"
import "unknown-type.rei"
import "../catalogues/broken.rei"
import "../catalogues/office.rei"
import "../catalogues/copy.rei"
import "catalogue-imports.rei"
testcase T {
  room R size 3 x 2 {
    object sofa : Sofa on F_1_0
    object arm : Armchair on F_2_0
    robot r : Scout on F_0_0
  }
  mission M { goto F_1_1 goto F_2_1 }
}
