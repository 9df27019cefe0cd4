// A catalogue whose robot is read from its URDF description (docs/robots.md): its footprint (a circle: the wheels
// are inside the body), its lidar's place and its wheels come from round_bot.urdf, the rest from this entry.
catalogue RoundRobots {
  robot type RoundBot : urdf "round_bot.urdf" mass 2.5 speed 0.3 turn 2.0
    lidar link "laser" beams 360 range 0.12 to 3.5 rate 10
}
