// Polygon footprints (docs/language.md#catalogues): each error at what is wrong, a crossing at its later edge's first vertex
// expect: 11:21 org.rei.dsl.polygon | A polygon has at least 3 vertices, got 2
// expect: 12:44 org.rei.dsl.polygon | The polygon crosses itself: its edge from vertex 3 to vertex 4 meets the edge from vertex 1 to vertex 2
// expect: 13:22 org.rei.dsl.polygon | The polygon has no area: its vertices lie on one line
// expect: 14:55 org.rei.dsl.nonPositive | The height must be above 0
// expect: 15:22 org.rei.dsl.typeCategory | Only furniture stands on a polygon: a dynamic type is a box or a cylinder
// expect: 16:43 org.rei.dsl.polygon | Vertex 3 repeats vertex 2
// (Fine is an L-shaped desk: concave, no error)

catalogue BadShapes {
  type Two : object polygon (0,0) (1,0) height 1
  type Bowtie : object polygon (0,0) (1,1) (1,0) (0,1) height 1
  type Line : object polygon (0,0) (1,0) (2.5,0) height 1
  type Flat : object polygon (0,0) (1,0) (0,1) height 0
  type Mat : dynamic polygon (0,0) (1,0) (0,1) height 0.1 mass 2
  type Twice : object polygon (0,0) (1,0) (1,0) (0,1) height 1
  type Fine : object polygon (0,0) (1.6,0) (1.6,0.6) (0.6,0.6) (0.6,1.4) (0,1.4) height 0.75
}
