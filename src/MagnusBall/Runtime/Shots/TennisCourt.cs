using System;

namespace MagnusBall.Shots
{
    /// <summary>
    /// The tennis court and net as data, in metres, from the ITF Rules of Tennis (2024), rule 1 (The Court; measured to the outside
    /// of the lines) and rule 2 (permanent fixtures), and a judge for a shot flown in the court's frame: origin on the ground at
    /// the centre of the hitter's baseline, forward toward the net (which stands at half the length), right across the court.
    /// </summary>
    public static class TennisCourt
    {
        /// <summary>Baseline to baseline, 23.77 m (78 ft; rule 1). The net stands at half of it, 11.885 m.</summary>
        public const double LengthMetres = 23.77;

        /// <summary>Width of the singles court, 8.23 m (27 ft; rule 1).</summary>
        public const double SinglesWidthMetres = 8.23;

        /// <summary>Width of the doubles court, 10.97 m (36 ft; rule 1).</summary>
        public const double DoublesWidthMetres = 10.97;

        /// <summary>Height of the net at the centre, 0.914 m (3 ft; rule 1).</summary>
        public const double NetHeightAtCentreMetres = 0.914;

        /// <summary>Height of the net at the posts, 1.07 m (3.5 ft; rule 1).</summary>
        public const double NetHeightAtPostsMetres = 1.07;

        /// <summary>The posts' centres stand this far outside the doubles sidelines, 0.914 m (3 ft; rule 1).</summary>
        public const double PostsOutsideDoublesMetres = 0.914;

        /// <summary>The service lines are this far from the net, 6.40 m (21 ft; rule 1).</summary>
        public const double ServiceLineFromNetMetres = 6.40;

        /// <summary>
        /// Judges a rally shot flown in the court's frame: <see cref="ShotOutcome.Net"/> when it passes the net lower than one ball
        /// radius above the net's top (the net taken to sag in a straight line from the posts to the centre), then
        /// <see cref="ShotOutcome.In"/>, <see cref="ShotOutcome.Out"/> (long), <see cref="ShotOutcome.Wide"/> or
        /// <see cref="ShotOutcome.Short"/> by where it first touches the ground.
        /// </summary>
        /// <param name="flight">The flight (<see cref="ShotFlyer.Fly"/> in the court's frame).</param>
        /// <param name="doubles">True to judge against the doubles sidelines.</param>
        /// <exception cref="ArgumentNullException">flight is null.</exception>
        public static ShotOutcome Judge(FlightSummary flight, bool doubles = false)
        {
            Require.NotNull(flight, nameof(flight));
            double net = LengthMetres / 2, posts = DoublesWidthMetres / 2 + PostsOutsideDoublesMetres;
            return Courts.Judge(flight, net, LengthMetres, (doubles ? DoublesWidthMetres : SinglesWidthMetres) / 2, posts,
                right => NetHeightAtCentreMetres + (NetHeightAtPostsMetres - NetHeightAtCentreMetres) * Math.Min(1, Math.Abs(right) / posts));
        }
    }

    /// <summary>
    /// The table-tennis table and net as data, in metres, from the ITTF Handbook (2024), rules 2.1 (the table) and 2.2 (the net
    /// assembly), and a judge for a shot flown in the table's frame: origin at the centre of the hitter's end line on the
    /// playing surface (0.76 m above the floor), forward along the table, right across it.
    /// </summary>
    public static class TableTennisTable
    {
        /// <summary>Length of the playing surface, 2.74 m (rule 2.1.1). The net stands at half of it, 1.37 m.</summary>
        public const double LengthMetres = 2.74;

        /// <summary>Width of the playing surface, 1.525 m (rule 2.1.1).</summary>
        public const double WidthMetres = 1.525;

        /// <summary>Height of the playing surface above the floor, 0.76 m (rule 2.1.1).</summary>
        public const double SurfaceHeightMetres = 0.76;

        /// <summary>Height of the top of the net above the playing surface, 15.25 cm (rule 2.2.3).</summary>
        public const double NetHeightMetres = 0.1525;

        /// <summary>How far the net's posts stand outside each sideline, 15.25 cm (rule 2.2.2).</summary>
        public const double NetOverhangMetres = 0.1525;

        /// <summary>
        /// Judges a rally shot flown in the table's frame: <see cref="ShotOutcome.Net"/> when it passes the net lower than one ball
        /// radius above its top, then by where it first comes down to the playing surface's plane: <see cref="ShotOutcome.In"/> on
        /// the opponent's half (edges included), <see cref="ShotOutcome.Out"/> beyond the end line, <see cref="ShotOutcome.Wide"/>
        /// beyond a sideline, <see cref="ShotOutcome.Short"/> before the net.
        /// </summary>
        /// <param name="flight">The flight (<see cref="ShotFlyer.Fly"/> in the table's frame).</param>
        /// <exception cref="ArgumentNullException">flight is null.</exception>
        public static ShotOutcome Judge(FlightSummary flight)
        {
            Require.NotNull(flight, nameof(flight));
            return Courts.Judge(flight, LengthMetres / 2, LengthMetres, WidthMetres / 2, WidthMetres / 2 + NetOverhangMetres, _ => NetHeightMetres);
        }
    }

    /// <summary>A net game's judge: the net, then the first landing.</summary>
    internal static class Courts
    {
        internal static ShotOutcome Judge(FlightSummary flight, double net, double length, double halfWidth, double posts, Func<double, double> netHeight)
        {
            double r = flight.BallRadiusMetres;
            if (!flight.TryCross(net, out double up, out double right))
            {
                return flight.Landed ? ShotOutcome.Short : ShotOutcome.Out;
            }

            if (Math.Abs(right) <= posts + r && up < netHeight(right) + r)
            {
                return ShotOutcome.Net;
            }

            if (!flight.Landed)
            {
                return ShotOutcome.Out;
            }

            Vector3d end = flight.End;
            return end.X > length ? ShotOutcome.Out
                : Math.Abs(end.Y) > halfWidth ? ShotOutcome.Wide
                : end.X < net ? ShotOutcome.Short
                : ShotOutcome.In;
        }
    }
}
