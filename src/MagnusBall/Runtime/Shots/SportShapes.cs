using System;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;

namespace MagnusBall.Shots
{
    /// <summary>
    /// A sport's fixtures as contact shapes, each a few lines from the official dimensions: a tennis net (cord, mesh and posts,
    /// from <see cref="TennisCourt"/>), a soccer goal's frame (from <see cref="SoccerGoal"/>), a basketball hoop (FIBA, below)
    /// and a table-tennis net (from <see cref="TableTennisTable"/>). Each builder places the fixture from a point on the ground
    /// and two directions, so it works in any frame. The contact parameters are game values (no measurement is fitted to them;
    /// docs/contacts.md).
    /// </summary>
    public static class SportShapes
    {
        /// <summary>FIBA Official Basketball Rules 2024, Basketball Equipment: the ring is 3.05 m above the floor.</summary>
        public const double RimHeightMetres = 3.05;

        /// <summary>FIBA Basketball Equipment: the ring's inside diameter, 0.45 m (0.450-0.459 m).</summary>
        public const double RimInnerDiameterMetres = 0.45;

        /// <summary>FIBA Basketball Equipment: the ring's steel is 16-20 mm thick; 18 mm here.</summary>
        public const double RimThicknessMetres = 0.018;

        /// <summary>FIBA Basketball Equipment: from the backboard's face to the nearest inside edge of the ring, 0.15 m (0.151 m).</summary>
        public const double RimFromBoardMetres = 0.15;

        /// <summary>FIBA Basketball Equipment: the backboard is 1.80 m wide.</summary>
        public const double BackboardWidthMetres = 1.80;

        /// <summary>FIBA Basketball Equipment: the backboard is 1.05 m high.</summary>
        public const double BackboardHeightMetres = 1.05;

        /// <summary>FIBA Basketball Equipment: the backboard's lower edge is 2.90 m above the floor.</summary>
        public const double BackboardLowerEdgeMetres = 2.90;

        /// <summary>ITTF Handbook rule 2.2.3: the net is 1.83 m long (the table's width plus 15.25 cm each side).</summary>
        public const double TableTennisNetLengthMetres = 1.83;

        /// <summary>The net cord's (or tape's) radius: 1 cm, a game value (the ITF rule 1 asks a band 5-6.35 cm deep over a cord).</summary>
        public const double TennisCordRadiusMetres = 0.01;

        /// <summary>A tennis net post's radius, 7.5 cm (ITF rule 1: posts at most 15 cm across).</summary>
        public const double TennisPostRadiusMetres = 0.075;

        /// <summary>The net cord and tape: restitution 0.3, friction 0.6 (game values).</summary>
        public static readonly ContactProperties NetCord = new ContactProperties(0.3, 0.6);

        /// <summary>Posts and bars (metal, painted): restitution 0.7, friction 0.3 (game values).</summary>
        public static readonly ContactProperties Post = new ContactProperties(0.7, 0.3);

        /// <summary>A basketball ring (steel): restitution 0.6, friction 0.3 (game values).</summary>
        public static readonly ContactProperties Rim = new ContactProperties(0.6, 0.3);

        /// <summary>A backboard (glass): restitution 0.75, friction 0.3 (game values).</summary>
        public static readonly ContactProperties Board = new ContactProperties(0.75, 0.3);

        /// <summary>
        /// A tennis net across the court: two cord capsules sagging in straight lines from 1.07 m at the posts to 0.914 m at the
        /// centre (their tops), the mesh below them, and the two posts 0.914 m outside the doubles sidelines. Ids: firstId (cord,
        /// left half), +1 (cord, right half), +2 (mesh), +3 and +4 (posts).
        /// </summary>
        /// <param name="firstId">The first of the five ids.</param>
        /// <param name="centreOnGround">The point on the ground under the net's centre, m; finite.</param>
        /// <param name="across">The direction along the net (across the court); finite, non-zero.</param>
        /// <param name="up">Up; finite, non-zero, not along <paramref name="across"/>.</param>
        /// <exception cref="ArgumentException">A vector is not finite, zero, or up is along across (the message names it).</exception>
        public static ContactShape[] TennisNet(int firstId, Vector3d centreOnGround, Vector3d across, Vector3d up)
        {
            Frame(across, up, out Vector3d a, out Vector3d u, out Vector3d n);
            double half = TennisCourt.DoublesWidthMetres / 2 + TennisCourt.PostsOutsideDoublesMetres;
            double r = TennisCordRadiusMetres;
            Vector3d centreTop = centreOnGround + u * (TennisCourt.NetHeightAtCentreMetres - r);
            Vector3d leftTop = centreOnGround - a * half + u * (TennisCourt.NetHeightAtPostsMetres - r);
            Vector3d rightTop = centreOnGround + a * half + u * (TennisCourt.NetHeightAtPostsMetres - r);
            double meshHeight = TennisCourt.NetHeightAtCentreMetres - 2 * r;
            return new ContactShape[]
            {
                new CapsuleShape(firstId, leftTop, centreTop, r, NetCord),
                new CapsuleShape(firstId + 1, centreTop, rightTop, r, NetCord),
                new NetMeshShape(firstId + 2, centreOnGround + u * (meshHeight / 2), n, a, 2 * half, meshHeight),
                new CylinderShape(firstId + 3, centreOnGround - a * (half + TennisPostRadiusMetres), centreOnGround - a * (half + TennisPostRadiusMetres) + u * TennisCourt.NetHeightAtPostsMetres, TennisPostRadiusMetres, Post),
                new CylinderShape(firstId + 4, centreOnGround + a * (half + TennisPostRadiusMetres), centreOnGround + a * (half + TennisPostRadiusMetres) + u * TennisCourt.NetHeightAtPostsMetres, TennisPostRadiusMetres, Post),
            };
        }

        /// <summary>
        /// A soccer goal's frame: two posts and the crossbar, cylinders of 0.12 m diameter, the goal 7.32 m wide and 2.44 m high
        /// between their inner edges. Ids: firstId (left post), +1 (right post), +2 (crossbar).
        /// </summary>
        /// <param name="firstId">The first of the three ids.</param>
        /// <param name="goalLineCentre">The point on the ground midway between the posts' centres, m; finite.</param>
        /// <param name="across">The direction along the goal line; finite, non-zero.</param>
        /// <param name="up">Up; finite, non-zero, not along <paramref name="across"/>.</param>
        /// <exception cref="ArgumentException">A vector is not finite, zero, or up is along across (the message names it).</exception>
        public static ContactShape[] SoccerGoalFrame(int firstId, Vector3d goalLineCentre, Vector3d across, Vector3d up)
        {
            Frame(across, up, out Vector3d a, out Vector3d u, out _);
            double r = SoccerGoal.PostWidthMetres / 2;
            double half = SoccerGoal.WidthMetres / 2 + r;
            double top = SoccerGoal.HeightMetres + 2 * r;
            Vector3d left = goalLineCentre - a * half, right = goalLineCentre + a * half;
            return new ContactShape[]
            {
                new CylinderShape(firstId, left, left + u * top, r, Post),
                new CylinderShape(firstId + 1, right, right + u * top, r, Post),
                new CylinderShape(firstId + 2, left + u * (top - r), right + u * (top - r), r, Post),
            };
        }

        /// <summary>
        /// A basketball hoop (FIBA): the ring, a torus 3.05 m up with a 0.45 m inside diameter, its inside edge 0.15 m from the
        /// backboard, and the backboard, a rectangle 1.80 x 1.05 m whose lower edge is 2.90 m up. Ids: firstId (ring), +1 (board).
        /// </summary>
        /// <param name="firstId">The first of the two ids.</param>
        /// <param name="boardFootOnGround">The point on the floor under the middle of the backboard's face, m; finite.</param>
        /// <param name="towardCourt">The backboard's face normal, toward the court; finite, non-zero.</param>
        /// <param name="up">Up; finite, non-zero, not along <paramref name="towardCourt"/>.</param>
        /// <exception cref="ArgumentException">A vector is not finite, zero, or up is along towardCourt (the message names it).</exception>
        public static ContactShape[] BasketballHoop(int firstId, Vector3d boardFootOnGround, Vector3d towardCourt, Vector3d up)
        {
            Frame(towardCourt, up, out Vector3d n, out Vector3d u, out Vector3d side);
            double tube = RimThicknessMetres / 2;
            double ring = RimInnerDiameterMetres / 2 + tube;
            Vector3d rimCentre = boardFootOnGround + u * RimHeightMetres + n * (RimFromBoardMetres + ring - tube);
            Vector3d boardCentre = boardFootOnGround + u * (BackboardLowerEdgeMetres + BackboardHeightMetres / 2);
            return new ContactShape[]
            {
                new TorusShape(firstId, rimCentre, u, ring, tube, Rim),
                BoxShape.Rectangle(firstId + 1, boardCentre, n, side, BackboardWidthMetres, BackboardHeightMetres, Board),
            };
        }

        /// <summary>
        /// A table-tennis net: the mesh, 1.83 m long and 15.25 cm high, with a thin cord along its top. Ids: firstId (cord), +1 (mesh).
        /// </summary>
        /// <param name="firstId">The first of the two ids.</param>
        /// <param name="centreOnSurface">The point on the playing surface under the net's centre, m; finite.</param>
        /// <param name="across">The direction along the net; finite, non-zero.</param>
        /// <param name="up">Up; finite, non-zero, not along <paramref name="across"/>.</param>
        /// <exception cref="ArgumentException">A vector is not finite, zero, or up is along across (the message names it).</exception>
        public static ContactShape[] TableTennisNet(int firstId, Vector3d centreOnSurface, Vector3d across, Vector3d up)
        {
            Frame(across, up, out Vector3d a, out Vector3d u, out Vector3d n);
            const double cord = 0.002; // a game value: a 4 mm binding along the top
            double half = TableTennisNetLengthMetres / 2, height = TableTennisTable.NetHeightMetres;
            Vector3d top = centreOnSurface + u * (height - cord);
            return new ContactShape[]
            {
                new CapsuleShape(firstId, top - a * half, top + a * half, cord, NetCord),
                new NetMeshShape(firstId + 1, centreOnSurface + u * ((height - 2 * cord) / 2), n, a, 2 * half, height - 2 * cord),
            };
        }

        // A right-handed frame from a first direction and up: a (unit first), u (up across it), n = a x u.
        private static void Frame(in Vector3d first, in Vector3d up, out Vector3d a, out Vector3d u, out Vector3d n)
        {
            a = Require.NonZero(first, nameof(first)).NormalizedOrZero();
            Vector3d v = Require.NonZero(up, nameof(up));
            v -= a * Vector3d.Dot(v, a);
            if (!(v.Length > 1e-9 * up.Length))
            {
                throw new ArgumentException($"up must not be along the first direction; got {first} and {up}.", nameof(up));
            }

            u = v.NormalizedOrZero();
            n = Vector3d.Cross(a, u);
        }
    }
}
