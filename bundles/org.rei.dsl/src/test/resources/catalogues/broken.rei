// Does not parse.
catalogue Broken {
  type X : object box 1 x
}
