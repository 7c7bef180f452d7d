#nullable enable
using System;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>A straight court line (or the net) on the ground, from <see cref="Start"/> to <see cref="End"/>, m.</summary>
    public readonly struct CourtLine
    {
        /// <summary>One end of the line, m (court frame).</summary>
        public readonly Vector3d Start;

        /// <summary>The other end of the line, m (court frame).</summary>
        public readonly Vector3d End;

        /// <summary>What the line is ("baseline", "service line", ...).</summary>
        public readonly string Name;

        /// <summary>Creates a line.</summary>
        /// <param name="name">What the line is.</param>
        /// <param name="start">One end, m.</param>
        /// <param name="end">The other end, m.</param>
        public CourtLine(string name, Vector3d start, Vector3d end)
        {
            Name = name;
            Start = start;
            End = end;
        }
    }

    /// <summary>The part of the court a shot must land in to be good.</summary>
    public enum TargetArea
    {
        /// <summary>The far singles court (a rally shot).</summary>
        FarSinglesCourt,

        /// <summary>The far deuce service box (the receiver's right, the server's left: +z).</summary>
        FarDeuceServiceBox,

        /// <summary>The far advantage service box (-z).</summary>
        FarAdServiceBox,
    }

    /// <summary>
    /// A tennis court to the ITF's dimensions, in the scene's frame, shared by the Unity scripts and the
    /// headless runner (no UnityEngine dependency).
    /// </summary>
    /// <remarks>
    /// <para><b>The frame.</b> Origin on the ground under the centre of the net; +x along the court from the
    /// hitter's baseline to the far one; +y up; +z to the hitter's left. These are Unity's own world axes
    /// with the camera looking down +x, exactly the thesis's scene ("positive X into the screen, Y up, Z to
    /// the left", Agrawal 2023, section 3.2). Unity's frame is left-handed, and the library runs directly in
    /// it: gravity is (0, -g, 0), positions and velocities are Unity's numbers unchanged, and spin is built by
    /// its effect (<see cref="MagnusBall.Spin.Topspin"/>, <see cref="MagnusBall.Spin.Toward"/>), which gives
    /// the right angular velocity in either handedness. Nothing is mirrored or sign-flipped anywhere.</para>
    /// <para>Dimensions (ITF Rules of Tennis, rule 1 and appendix; the ITF's figures are the library's data,
    /// <c>MagnusBall.Shots.TennisCourt</c>): 23.77 m long; 10.97 m wide (doubles),
    /// 8.23 m (singles); service lines 6.40 m from the net; net 0.914 m high at the centre and 1.07 m at the
    /// posts, whose centres are 0.914 m outside the doubles sidelines. Measurements are to the outside of the
    /// lines, so a ball whose contact point touches a line is in.</para>
    /// </remarks>
    public static class TennisCourt
    {
        /// <summary>Court length, baseline to baseline, m.</summary>
        public const double Length = global::MagnusBall.Shots.TennisCourt.LengthMetres;

        /// <summary>Doubles court width, m.</summary>
        public const double DoublesWidth = global::MagnusBall.Shots.TennisCourt.DoublesWidthMetres;

        /// <summary>Singles court width, m.</summary>
        public const double SinglesWidth = global::MagnusBall.Shots.TennisCourt.SinglesWidthMetres;

        /// <summary>Distance of each service line from the net, m.</summary>
        public const double ServiceLineFromNet = global::MagnusBall.Shots.TennisCourt.ServiceLineFromNetMetres;

        /// <summary>Net height at the centre strap, m.</summary>
        public const double NetHeightAtCentre = global::MagnusBall.Shots.TennisCourt.NetHeightAtCentreMetres;

        /// <summary>Net height at the posts, m.</summary>
        public const double NetHeightAtPosts = global::MagnusBall.Shots.TennisCourt.NetHeightAtPostsMetres;

        /// <summary>How far outside the doubles sideline each net post stands, m.</summary>
        public const double PostOutsideDoubles = global::MagnusBall.Shots.TennisCourt.PostsOutsideDoublesMetres;

        /// <summary>Width of the lines, m (5 cm; the baseline may be up to 10 cm).</summary>
        public const double LineWidth = 0.05;

        /// <summary>Length of the centre mark, m.</summary>
        public const double CentreMarkLength = 0.10;

        /// <summary>The thesis's serving height (Agrawal 2023, section 3.2): the ball 2.87 m above the court.</summary>
        public const double ServeHeight = 2.87;

        /// <summary>Half the court length: the baselines are at x = -/+ this, m.</summary>
        public const double HalfLength = Length / 2;

        /// <summary>Half the doubles width, m.</summary>
        public const double HalfDoublesWidth = DoublesWidth / 2;

        /// <summary>Half the singles width, m.</summary>
        public const double HalfSinglesWidth = SinglesWidth / 2;

        /// <summary>Distance of each net post from the centre line, m.</summary>
        public const double PostOffset = HalfDoublesWidth + PostOutsideDoubles;

        /// <summary>Downrange, from the hitter's baseline toward the far one: +x.</summary>
        public static Vector3d Downrange => Vector3d.UnitX;

        /// <summary>Up: +y (gravity is -y).</summary>
        public static Vector3d Up => Vector3d.UnitY;

        /// <summary>The hitter's left: +z.</summary>
        public static Vector3d Left => Vector3d.UnitZ;

        /// <summary>
        /// Height of the top of the net at lateral position <paramref name="z"/>, m: 0.914 m at the centre
        /// strap rising to 1.07 m at the posts. The cord is taken as straight from strap to post (a real
        /// cord sags a little between them).
        /// </summary>
        /// <param name="z">Lateral position, m.</param>
        public static double NetHeightAt(double z)
        {
            double fraction = Math.Min(Math.Abs(z) / PostOffset, 1.0);
            return NetHeightAtCentre + (NetHeightAtPosts - NetHeightAtCentre) * fraction;
        }

        /// <summary>The court's lines and the net's foot, on the ground, for drawing (a new array each call).</summary>
        public static CourtLine[] Lines()
        {
            double x = HalfLength, d = HalfDoublesWidth, s = HalfSinglesWidth, service = ServiceLineFromNet;
            return new[]
            {
                new CourtLine("near baseline", P(-x, -d), P(-x, d)),
                new CourtLine("far baseline", P(x, -d), P(x, d)),
                new CourtLine("doubles sideline", P(-x, -d), P(x, -d)),
                new CourtLine("doubles sideline", P(-x, d), P(x, d)),
                new CourtLine("singles sideline", P(-x, -s), P(x, -s)),
                new CourtLine("singles sideline", P(-x, s), P(x, s)),
                new CourtLine("near service line", P(-service, -s), P(-service, s)),
                new CourtLine("far service line", P(service, -s), P(service, s)),
                new CourtLine("centre service line", P(-service, 0), P(service, 0)),
                new CourtLine("near centre mark", P(-x, 0), P(-x + CentreMarkLength, 0)),
                new CourtLine("far centre mark", P(x, 0), P(x - CentreMarkLength, 0)),
            };
        }

        /// <summary>
        /// True when a ball whose contact point is (<paramref name="x"/>, <paramref name="z"/>) lands in
        /// <paramref name="area"/> (lines count as in).
        /// </summary>
        /// <param name="area">The target area.</param>
        /// <param name="x">Downrange position of the contact point, m.</param>
        /// <param name="z">Lateral position of the contact point, m.</param>
        public static bool IsIn(TargetArea area, double x, double z)
        {
            switch (area)
            {
                case TargetArea.FarSinglesCourt:
                    return x >= 0 && x <= HalfLength && Math.Abs(z) <= HalfSinglesWidth;
                case TargetArea.FarDeuceServiceBox:
                    return x >= 0 && x <= ServiceLineFromNet && z >= 0 && z <= HalfSinglesWidth;
                case TargetArea.FarAdServiceBox:
                    return x >= 0 && x <= ServiceLineFromNet && z <= 0 && z >= -HalfSinglesWidth;
                default:
                    throw new ArgumentOutOfRangeException(nameof(area), area, "area must be a TargetArea value.");
            }
        }

        private static Vector3d P(double x, double z) => new Vector3d(x, 0, z);
    }
}
