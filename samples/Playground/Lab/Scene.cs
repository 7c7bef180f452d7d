using System;
using System.Collections.Generic;
using MagnusBall.Flight;

namespace MagnusBall.Playground.Lab
{
    /// <summary>A line of a court or field, drawn in the top view (metres, x downrange, y to the left).</summary>
    public readonly struct SceneLine
    {
        /// <summary>A line from (x1, y1) to (x2, y2) on the ground.</summary>
        public SceneLine(double x1, double y1, double x2, double y2)
        {
            X1 = x1;
            Y1 = y1;
            X2 = x2;
            Y2 = y2;
        }

        /// <summary>Start, downrange, m.</summary>
        public double X1 { get; }

        /// <summary>Start, to the left, m.</summary>
        public double Y1 { get; }

        /// <summary>End, downrange, m.</summary>
        public double X2 { get; }

        /// <summary>End, to the left, m.</summary>
        public double Y2 { get; }
    }

    /// <summary>A segment drawn in the side view (metres: x downrange, z up), with its CSS class and a title.</summary>
    public readonly struct SideSegment
    {
        /// <summary>A segment from (x1, z1) to (x2, z2).</summary>
        public SideSegment(double x1, double z1, double x2, double z2, string cssClass, string title)
        {
            X1 = x1;
            Z1 = z1;
            X2 = x2;
            Z2 = z2;
            CssClass = cssClass;
            Title = title;
        }

        /// <summary>Start downrange, m.</summary>
        public double X1 { get; }

        /// <summary>Start height, m.</summary>
        public double Z1 { get; }

        /// <summary>End downrange, m.</summary>
        public double X2 { get; }

        /// <summary>End height, m.</summary>
        public double Z2 { get; }

        /// <summary>"obstacle" (black) or "target" (orange).</summary>
        public string CssClass { get; }

        /// <summary>What it is.</summary>
        public string Title { get; }
    }

    /// <summary>
    /// Where a shot is played: the lines drawn in the top view, the net, wall, goal, plate or ring drawn in the side
    /// view, the planes whose crossings the flight reports (the first is the obstacle the clearance is measured over,
    /// where the scene has one), the verdict on a flight, and the default launch. Heights are above the playing
    /// surface, which is the ground of the flight (the landing is where the ball's centre comes down to it, as in the
    /// library's validation cases). The dimensions are the sports' official ones: ITF Rules of Tennis (rule 1), IFAB
    /// Laws of the Game (laws 1 and 13), ITTF Handbook (2.1, 2.2), FIBA Official Basketball Rules (art. 2 and 3), MLB
    /// Official Baseball Rules (2.01, 5.04, the strike zone in "Definitions"); where a number is a typical play value,
    /// not a rule, its comment says so.
    /// </summary>
    public sealed class Scene
    {
        private readonly Func<ShotResult, string> _verdict;

        private Scene(
            string sport, double length, double halfWidth, SceneLine[] lines, SideSegment[] side, Plane[] planes, string[] planeNames,
            double obstacleHeight, string obstacleName, Func<ShotResult, string> verdict, ShotSettings launch)
        {
            Sport = sport;
            Length = length;
            HalfWidth = halfWidth;
            Lines = lines;
            Side = side;
            Planes = planes;
            PlaneNames = planeNames;
            ObstacleHeight = obstacleHeight;
            ObstacleName = obstacleName;
            _verdict = verdict;
            Launch = launch;
        }

        /// <summary>The sport's name.</summary>
        public string Sport { get; }

        /// <summary>How far downrange the view reaches at least, m.</summary>
        public double Length { get; }

        /// <summary>Half the width the top view shows at least, m.</summary>
        public double HalfWidth { get; }

        /// <summary>The court or field lines, m.</summary>
        public IReadOnlyList<SceneLine> Lines { get; }

        /// <summary>What the side view draws: the net, the wall, the goal, the strike zone, the ring and board.</summary>
        public IReadOnlyList<SideSegment> Side { get; }

        /// <summary>The planes whose crossings the flight reports, in the order of <see cref="FlightEvent.PlaneIndex"/>.</summary>
        public Plane[] Planes { get; }

        /// <summary>What each of <see cref="Planes"/> is ("the net", "the goal line").</summary>
        public IReadOnlyList<string> PlaneNames { get; }

        /// <summary>Height of the obstacle (the first plane) above the playing surface, m; 0 where the scene has none.</summary>
        public double ObstacleHeight { get; }

        /// <summary>What the obstacle is ("net", "wall"); empty where the scene has none.</summary>
        public string ObstacleName { get; }

        /// <summary>The default launch for this sport (speed, angles, spin, height).</summary>
        public ShotSettings Launch { get; }

        /// <summary>The outcome of a flight that landed, in the sport's terms ("in", "into the net", "goal", "strike"...).</summary>
        public string Verdict(ShotResult result) => _verdict(result);

        /// <summary>The scene for a preset name (golf variants share golf's; tennis-free-flight shares tennis's).</summary>
        public static Scene For(string presetName)
        {
            string name = presetName ?? string.Empty;
            if (name.StartsWith("tennis", StringComparison.Ordinal))
            {
                return Tennis;
            }

            if (name.StartsWith("golf", StringComparison.Ordinal))
            {
                return Golf;
            }

            switch (name)
            {
                case "soccer": return Soccer;
                case "baseball": return Baseball;
                case "table-tennis": return TableTennis;
                case "basketball": return Basketball;
                default: return Tennis;
            }
        }

        private static Plane Across(double x) => new Plane(new Vector3d(x, 0, 0), Vector3d.UnitX);

        // ITF rule 1: 23.77 m long, singles 8.23 m and doubles 10.97 m wide, the net 0.914 m high at the centre,
        // the service lines 6.40 m from the net. The ball is hit from the baseline at 1 m, as in Cross's case.
        private static readonly Scene Tennis = new Scene(
            "tennis", 26, 6.5,
            new[]
            {
                new SceneLine(0, -5.485, 0, 5.485), new SceneLine(23.77, -5.485, 23.77, 5.485),
                new SceneLine(0, -5.485, 23.77, -5.485), new SceneLine(0, 5.485, 23.77, 5.485),
                new SceneLine(0, -4.115, 23.77, -4.115), new SceneLine(0, 4.115, 23.77, 4.115),
                new SceneLine(5.485, -4.115, 5.485, 4.115), new SceneLine(18.285, -4.115, 18.285, 4.115),
                new SceneLine(5.485, 0, 18.285, 0), new SceneLine(11.885, -6.4, 11.885, 6.4),
            },
            new[] { new SideSegment(11.885, 0, 11.885, 0.914, "obstacle", "net, 0.914 m at the centre") },
            new[] { Across(11.885) }, new[] { "the net" }, 0.914, "net",
            r => !double.IsNaN(r.Clearance) && r.Clearance < -2 * r.BallRadius ? "into the net" : !Cleared(r) ? "clips the net cord" : Ends(r).X < 11.885 ? "short of the net"
                : Ends(r).X <= 23.77 && Math.Abs(Ends(r).Y) <= 4.115 ? "in (singles court)" : "out",
            new ShotSettings { Preset = "tennis", SpeedMetresPerSecond = 30, ElevationDegrees = 6, TopspinRpm = 1200, LaunchHeightMetres = 1.0 });

        // IFAB laws 1 and 13: a free kick 20 m out, the wall 9.15 m away (1.8 m tall and 3 m wide: a typical jumping
        // wall, not a rule), the goal 7.32 m wide and 2.44 m high. Javorova & Ivanov's kick: 24.15 m/s with 61.86
        // rad/s (590.7 rpm) of sidespin, at the angles that take it to 3.2 m across and 2.2 m up on the goal line.
        private static readonly Scene Soccer = new Scene(
            "soccer", 24, 8,
            new[]
            {
                new SceneLine(20, -8, 20, 8), new SceneLine(20, -3.66, 22, -3.66), new SceneLine(20, 3.66, 22, 3.66),
                new SceneLine(22, -3.66, 22, 3.66), new SceneLine(9.15, -1.5, 9.15, 1.5),
            },
            new[] { new SideSegment(9.15, 0, 9.15, 1.8, "obstacle", "wall, 1.8 m"), new SideSegment(20, 0, 20, 2.44, "target", "goal, 2.44 m") },
            new[] { Across(9.15), Across(20) }, new[] { "the wall", "the goal line" }, 1.8, "wall",
            r =>
            {
                FlightEvent? wall = r.Crossing(0);
                if (wall is FlightEvent w && Math.Abs(w.Position.Y) < 1.5 + 0.11 && w.Position.Z < 1.8 + 0.11)
                {
                    return "blocked by the wall";
                }

                // The whole ball inside the frame: its centre more than a radius (0.11 m) inside the posts and under the bar.
                FlightEvent? line = r.Crossing(1);
                return line is FlightEvent g
                    ? Math.Abs(g.Position.Y) < 3.66 - 0.11 && g.Position.Z < 2.44 - 0.11 ? "goal" : "misses the frame"
                    : "short of the goal";
            },
            new ShotSettings { Preset = "soccer", SpeedMetresPerSecond = 24.15, ElevationDegrees = 19.3, DirectionDegrees = -0.3, TopspinRpm = 0, SidespinRpm = 590.7, LaunchHeightMetres = 0.11 });

        // MLB rules 2.01 and 5.04: the rubber 60 ft 6 in (18.44 m) from the plate's point; a release about 6 ft in
        // front of it at 1.8 m (typical Statcast extension and release height, not a rule); the plate 17 in (0.432 m)
        // wide, its front edge 16.61 m from the release; the zone from the knees to the letters, about 0.46-1.07 m for
        // a typical batter (Statcast's average sz_bot and sz_top, not a rule).
        private static readonly Scene Baseball = new Scene(
            "baseball", 18, 1.5,
            new[] { new SceneLine(16.61, -0.216, 16.61, 0.216), new SceneLine(16.61, -0.216, 17.04, -0.216), new SceneLine(16.61, 0.216, 17.04, 0.216) },
            new[] { new SideSegment(16.61, 0.46, 16.61, 1.07, "target", "strike zone, 0.46-1.07 m") },
            new[] { Across(16.61) }, new[] { "the front of the plate" }, 0, string.Empty,
            r =>
            {
                // A strike if any part of the ball (radius 0.0366 m) passes through the zone over the plate.
                FlightEvent? plate = r.Crossing(0);
                return plate is FlightEvent p && Math.Abs(p.Position.Y) <= 0.216 + 0.0366 && p.Position.Z >= 0.46 - 0.0366 && p.Position.Z <= 1.07 + 0.0366
                    ? "strike" : "ball";
            },
            new ShotSettings { Preset = "baseball", SpeedMetresPerSecond = 40, ElevationDegrees = -2.4, TopspinRpm = -2200, LaunchHeightMetres = 1.8, MaxFlightSeconds = 3 });

        // A fairway with 50 m marks; the tee is at the ball's own height.
        private static readonly Scene Golf = new Scene(
            "golf", 300, 25,
            new[]
            {
                new SceneLine(50, -20, 50, 20), new SceneLine(100, -20, 100, 20), new SceneLine(150, -20, 150, 20),
                new SceneLine(200, -20, 200, 20), new SceneLine(250, -20, 250, 20), new SceneLine(0, -20, 300, -20), new SceneLine(0, 20, 300, 20),
            },
            Array.Empty<SideSegment>(), Array.Empty<Plane>(), Array.Empty<string>(), 0, string.Empty,
            r => Math.Abs(Ends(r).Y) <= 20 ? "on the fairway" : "in the rough",
            new ShotSettings { Preset = "golf", SpeedMetresPerSecond = 74, ElevationDegrees = 10.9, TopspinRpm = -2686, LaunchHeightMetres = 0.0214, MaxFlightSeconds = 12 });

        // ITTF 2.1 and 2.2: the table 2.74 m by 1.525 m, the net 15.25 cm high across its middle. Heights are above
        // the table top; the ball is hit from just behind the end line, 20 cm above the table.
        private static readonly Scene TableTennis = new Scene(
            "table tennis", 3.2, 1.0,
            new[]
            {
                new SceneLine(0, -0.7625, 2.74, -0.7625), new SceneLine(0, 0.7625, 2.74, 0.7625), new SceneLine(0, -0.7625, 0, 0.7625),
                new SceneLine(2.74, -0.7625, 2.74, 0.7625), new SceneLine(0, 0, 2.74, 0), new SceneLine(1.37, -0.9, 1.37, 0.9),
            },
            new[] { new SideSegment(1.37, 0, 1.37, 0.1525, "obstacle", "net, 15.25 cm"), new SideSegment(0, 0, 2.74, 0, "target", "table") },
            new[] { Across(1.37) }, new[] { "the net" }, 0.1525, "net",
            r => !double.IsNaN(r.Clearance) && r.Clearance < -2 * r.BallRadius ? "into the net" : !Cleared(r) ? "clips the net" : Ends(r).X < 1.37 ? "short of the net"
                : Ends(r).X <= 2.74 && Math.Abs(Ends(r).Y) <= 0.7625 ? "on the table" : "off the table",
            new ShotSettings { Preset = "table-tennis", SpeedMetresPerSecond = 9, ElevationDegrees = 12, TopspinRpm = 3000, LaunchHeightMetres = 0.2, MaxFlightSeconds = 3 });

        // FIBA art. 2 and 3: the ring 3.05 m high, 0.45 m across, its centre 1.575 m from the end line and 0.375 m in
        // front of the board (1.05 m tall, its lower edge 2.90 m up); the free-throw line 5.80 m from the end line,
        // so 4.225 m to the ring's centre. A release at 2.1 m (a typical shooter, not a rule) at the speed and angle
        // that put the ball's centre through the ring's centre.
        private static readonly Scene Basketball = new Scene(
            "basketball", 6, 2,
            new[] { new SceneLine(0, -1.8, 0, 1.8), new SceneLine(4.6, -0.9, 4.6, 0.9), new SceneLine(4.0, 0, 4.45, 0) },
            new[] { new SideSegment(4.0, 3.05, 4.45, 3.05, "target", "ring, 3.05 m"), new SideSegment(4.6, 2.9, 4.6, 3.95, "obstacle", "backboard") },
            new[] { new Plane(new Vector3d(0, 0, 3.05), -Vector3d.UnitZ) }, new[] { "the ring's height" }, 0, string.Empty,
            r =>
            {
                // The ring's plane is watched downward (its normal points down): the crossing is the descent through
                // it. Through the ring: the centre more than a ball radius (0.12 m) inside its 0.225 m radius, so
                // the ball touches nothing.
                foreach (FlightEvent e in r.Events)
                {
                    if (e.Kind == FlightEventKinds.PlaneCrossing && e.Velocity.Z < 0)
                    {
                        double dx = e.Position.X - 4.225, dy = e.Position.Y;
                        return Math.Sqrt(dx * dx + dy * dy) < 0.225 - 0.12 ? "swish: through the ring" : "misses the ring";
                    }
                }

                return "short of the ring";
            },
            new ShotSettings { Preset = "basketball", SpeedMetresPerSecond = 7.6, ElevationDegrees = 44.1, TopspinRpm = -120, LaunchHeightMetres = 2.1, MaxFlightSeconds = 3 });

        private static Vector3d Ends(ShotResult r) => r.End.Position;

        // The ball's bottom passes over the tape (Clearance is measured from the bottom): a centre within a radius of
        // the tape touches it, which the flight does not model yet (no contact with the net), so the verdict says so.
        private static bool Cleared(ShotResult r) => double.IsNaN(r.Clearance) || r.Clearance > 0;
    }
}
