using System;

namespace MagnusBall.Shots
{
    /// <summary>
    /// The soccer goal as data, in metres, from the IFAB Laws of the Game 2024/25, law 1 (The Field of Play: 1.10 Goals) and
    /// law 13 (free kicks), and a judge for a shot flown toward it: the frame's forward points from the kick toward the goal line.
    /// </summary>
    public static class SoccerGoal
    {
        /// <summary>Distance between the inner edges of the posts, 7.32 m (8 yd; law 1.10).</summary>
        public const double WidthMetres = 7.32;

        /// <summary>Distance from the ground to the lower edge of the crossbar, 2.44 m (8 ft; law 1.10).</summary>
        public const double HeightMetres = 2.44;

        /// <summary>The largest width and depth of the posts and crossbar, 0.12 m (5 in; law 1.10); used as their thickness.</summary>
        public const double PostWidthMetres = 0.12;

        /// <summary>How far the defending wall must stand from the ball at a free kick, 9.15 m (10 yd; law 13.2).</summary>
        public const double WallDistanceMetres = 9.15;

        /// <summary>
        /// Judges a shot at the goal: it is <see cref="ShotOutcome.In"/> when the ball passes the goal line's front edge (the
        /// posts' front face) between the posts and under the crossbar (law 10.1 asks for the whole ball past the line's back
        /// edge, 12 cm further: a ball that comes down on the line itself, which the judge does not follow, counts as in), <see cref="ShotOutcome.Woodwork"/> when
        /// it strikes a post or the bar, <see cref="ShotOutcome.Wide"/> or <see cref="ShotOutcome.Over"/> when it passes
        /// outside them, and <see cref="ShotOutcome.Short"/> when it comes down before the line (a bounce is not followed).
        /// </summary>
        /// <param name="flight">The flight (<see cref="ShotFlyer.Fly"/>).</param>
        /// <param name="goalLineForwardMetres">Distance along forward from the frame's origin to the goal line, m; finite.</param>
        /// <param name="goalCentreRightMetres">How far right of the forward axis the middle of the goal is, m; finite.</param>
        /// <exception cref="ArgumentException">flight is null or a distance is not finite.</exception>
        public static ShotOutcome Judge(FlightSummary flight, double goalLineForwardMetres, double goalCentreRightMetres = 0)
        {
            Require.NotNull(flight, nameof(flight));
            Require.Finite(goalLineForwardMetres, nameof(goalLineForwardMetres));
            Require.Finite(goalCentreRightMetres, nameof(goalCentreRightMetres));
            double r = flight.BallRadiusMetres;
            if (!flight.TryCross(goalLineForwardMetres, out double up, out double right))
            {
                return ShotOutcome.Short;
            }

            double side = Math.Abs(right - goalCentreRightMetres), half = WidthMetres / 2;
            if (side >= half + PostWidthMetres + r)
            {
                return ShotOutcome.Wide;
            }

            if (up >= HeightMetres + PostWidthMetres + r)
            {
                return ShotOutcome.Over;
            }

            return side <= half - r && up <= HeightMetres - r ? ShotOutcome.In : ShotOutcome.Woodwork;
        }
    }

    /// <summary>
    /// Baseball's pitching distances as data, in metres, from the MLB Official Baseball Rules (2024), rule 2.01 and its
    /// diagrams (the front of the pitcher's plate stands 60 ft 6 in from the back point of home plate) and rule 2.02 (home plate,
    /// 17 in square with two corners cut). A pitch is
    /// flown in the frame of <see cref="ShotFlyer.Pitch"/>: origin at the front of the pitcher's plate on the field, forward
    /// toward home plate.
    /// </summary>
    public static class BaseballField
    {
        /// <summary>Front of the pitcher's plate to the back point of home plate, 60 ft 6 in = 18.4404 m (rule 2.01).</summary>
        public const double RubberToPlateMetres = 18.4404;

        /// <summary>Home plate's width and depth from its front edge to its back point, 17 in = 0.4318 m (rule 2.02).</summary>
        public const double PlateDepthMetres = 0.4318;

    }
}
