// Declares two of office.rei's type names again.
catalogue Copy {
  type Sofa : object box 1 x 1 x 1
  type Lamp : object cylinder 0.2 x 0.2 x 1.5
  robot type Scout : box 0.3 x 0.25 x 0.2 mass 4.5
}
