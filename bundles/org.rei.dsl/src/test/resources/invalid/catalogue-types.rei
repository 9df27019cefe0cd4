// expect: 11:8 org.rei.dsl.duplicateName | Type Table is in the default catalogue already
// expect: 14:8 org.rei.dsl.duplicateName | Duplicate type name 'Drum': already declared on line 12
// expect: 12:37 org.rei.dsl.cylinderSize | A cylinder stands on a circle
// expect: 12:52 org.rei.dsl.colour | Colour 'red': expected #RRGGBB or #RRGGBBAA
// expect: 13:3 org.rei.dsl.nonPositive | A human moves in the simulator: its mass must be above 0 kg
// expect: 14:26 org.rei.dsl.nonPositive | The x size must be above 0
// expect: 14:41 org.rei.dsl.nonPositive | The mass must not be negative
// expect: 16:7 org.rei.dsl.outOfRange | A robot's body must be at least 0.05 m high
// expect: 16:37 org.rei.dsl.nonPositive | The distance between the wheels must be above 0
catalogue Bad {
  type Table : object box 1 x 1 x 1
  type Drum : object cylinder 0.4 x 0.5 x 1 colour "red"
  type Walker : human cylinder 0.5 x 0.5 x 1.7
  type Drum : object box 0 x 1 x 1 mass -2
  robot type Tiny : box 0.1 x 0.1
    x 0.02 mass 1 wheels 0.03 apart 0
}
