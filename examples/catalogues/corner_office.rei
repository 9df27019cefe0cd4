// Furniture that is not a box: a corner desk and a corner sofa, each standing on a polygon (its vertices (x,y) in
// metres, in order round the outline, in the type's own frame). Like a box, the polygon's bounding box is centred
// on the floor the object stands on, and `yaw` turns it about that centre (docs/language.md#catalogues).
catalogue CornerOffice {
  // an L-shaped corner desk, 2.2 x 2.0 m, its arms 0.7 m deep: the long arm along x, the other up the left side
  type CornerDesk : object polygon (0,0) (2.2,0) (2.2,0.7) (0.7,0.7) (0.7,2.0) (0,2.0) height 0.75 mass 30
    colour "#A0785A"
  // a corner sofa with a bevelled outer corner
  type CornerSofa : object polygon (0,0) (1.8,0) (1.8,0.8) (0.8,0.8) (0.8,1.8) (0.3,1.8) (0,1.5) height 0.8
    mass 60 colour "#5A6E8C"
}
