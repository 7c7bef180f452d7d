#nullable enable
using MagnusBall.Contact.Swings;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>
    /// The scene's six shots made by racket swings (<see cref="TennisSwing"/>), hit from the same points as
    /// <see cref="StandardShots"/>. The racket speed, path, face turn and impact point are chosen here so the launches
    /// are like the standard shots' (a serve from a ball at rest, rally shots from a ball arriving at 10-15 m/s);
    /// the face tilt and azimuth were then solved by the library's inverse (<see cref="MagnusBall.Queries.SwingAim"/>, through
    /// <see cref="ShotSimulation.AimSwing"/>) so that each lands where its standard shot lands with the scene's default
    /// settings, and rounded to 0.001 deg (tests/MagnusBall.UnityScripts.Tests/SwingShotTests.cs checks both).
    /// </summary>
    public static class StandardSwings
    {
        /// <summary>The ball as a rally shot arrives: 14 m/s toward the hitter, descending at 1 m/s (each rally swing gives it 1000 rpm of topspin).</summary>
        public static Vector3d RallyBall => new Vector3d(-14, -1, 0);

        /// <summary>A flat first serve: a fast swing, nearly level, at the centre of the strings.</summary>
        public static TennisSwing FlatServe => new TennisSwing(
            "flat serve", StandardShots.FlatServe.Start, Vector3d.Zero, 0,
            new RacketSwing(34, 0, -6.845, RacketSwing.CentreRestitution, -9.000), TargetArea.FarDeuceServiceBox);

        /// <summary>A kick serve: a slower swing brushing steeply up and across the ball.</summary>
        public static TennisSwing KickServe => new TennisSwing(
            "kick serve", StandardShots.KickServe.Start, Vector3d.Zero, 0,
            new RacketSwing(35, 26, -10.775, RacketSwing.CentreRestitution, -23.546, 15), TargetArea.FarDeuceServiceBox);

        /// <summary>A topspin forehand: low to high.</summary>
        public static TennisSwing TopspinForehand => new TennisSwing(
            "topspin forehand", StandardShots.TopspinForehand.Start, RallyBall, 1000,
            new RacketSwing(26, 42, 0.320, RacketSwing.CentreRestitution, -10.394), TargetArea.FarSinglesCourt);

        /// <summary>A slice backhand: high to low with an open face.</summary>
        public static TennisSwing SliceBackhand => new TennisSwing(
            "slice backhand", StandardShots.SliceBackhand.Start, RallyBall, 1000,
            new RacketSwing(14, -26, 11.267, RacketSwing.CentreRestitution, 0.654), TargetArea.FarSinglesCourt);

        /// <summary>A topspin lob: steeply up under an open face.</summary>
        public static TennisSwing Lob => new TennisSwing(
            "topspin lob", StandardShots.Lob.Start, RallyBall, 1000,
            new RacketSwing(17, 64, 9.547, RacketSwing.CentreRestitution, -1.231), TargetArea.FarSinglesCourt);

        /// <summary>A drop shot: a slow chop under a very open face.</summary>
        public static TennisSwing DropShot => new TennisSwing(
            "drop shot", StandardShots.DropShot.Start, RallyBall, 1000,
            new RacketSwing(6, -40, 10.132, RacketSwing.CentreRestitution, -2.637), TargetArea.FarSinglesCourt);

        /// <summary>All six, in the order of <see cref="StandardShots.All"/>.</summary>
        public static TennisSwing[] All() => new[] { FlatServe, KickServe, TopspinForehand, SliceBackhand, Lob, DropShot };
    }
}
