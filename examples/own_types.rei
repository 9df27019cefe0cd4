// A test case with the office's own furniture and robot: the types come from a user catalogue that this file
// imports (paths are relative to this file); the default catalogue's types (Table, Human, ...) stay usable.
import "catalogues/office.rei"

testcase OwnTypes {
  room Lounge size 5 x 4 {
    object sofa : Sofa on F_2_1
    object pillar : Pillar on F_2_3
    object plant : Plant on F_4_0
    object desk : Table on F_0_3
    robot burger : Burger on F_0_0
  }
  mission AcrossTheLounge {
    goto F_4_2 within 90s
    goto F_0_1 within 90s
  }
}
