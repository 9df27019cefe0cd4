// A corridor of three floors written out: a room in the floor-graph form, which the editor can grow.
testcase Corridor {
  room Hall {
    // the corridor's comment stays
    floor A right B
    floor B right C
    floor C
    robot tb3 : Waffle on A
  }
  mission Through {
    goto C
    goto B
  }
}
