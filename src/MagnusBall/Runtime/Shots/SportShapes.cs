using System;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;

namespace MagnusBall.Shots
{
    /// <summary>
    /// A sport's fixtures as contact shapes, each a few lines from the official dimensions: a tennis net (cord, mesh and posts,
    /// from <see cref="TennisCourt"/>), a soccer goal's frame (from <see cref="SoccerGoal"/>), a basketball hoop (FIBA, below)
    /// and a table-tennis net (from <see cref="TableTennisTable"/>). Each builder places the fixture from a point on the ground
    /// and two directions, so it works in any frame. The restitutions of the posts and the backboard are taken from the
    /// sports' ball-rebound rules and the ring's is checked against the ring rule; the frictions and the net cord's restitution
    /// are game values (docs/contacts.md).
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

        /// <summary>
        /// Posts and bars (metal, painted): restitution 0.765, friction 0.3. The restitution is the ball's on a hard surface, from
        /// the ball-rebound rules (data/published/ball-rebound-rules.json): inside the ITF's band for a tennis ball (0.756-0.790,
        /// or 0.737-0.771 with the rebound read to the top of the ball) and FIFA's for a soccer ball read to the top (0.709-0.886;
        /// read to the bottom FIFA's starts at 0.791, which no value inside the ITF's meets). The friction is a game value.
        /// </summary>
        public static readonly ContactProperties Post = new ContactProperties(0.765, 0.3);

        /// <summary>
        /// A basketball ring (steel): restitution 0.6, friction 0.3 (game values). The restitution lies inside the band the
        /// NCAA/FIBA ring rule gives with the FIBA ball's (the ring absorbs 35-50 % of a drop's energy: e 0.534-0.671;
        /// data/published/ball-rebound-rules.json, checked in the validation tests).
        /// </summary>
        public static readonly ContactProperties Rim = new ContactProperties(0.6, 0.3);

        /// <summary>The rectangles the tennis net's mesh is made of, on each side of the centre: 6, so the mesh stays within 2.6 cm
        /// of the sagging cord (0.156 m of sag over 6.4 m).</summary>
        public const int TennisMeshPiecesPerHalf = 6;

        /// <summary>
        /// A backboard (glass): restitution 0.8, friction 0.3. The restitution is the FIBA ball's on the playing surface (dropped
        /// 1.80 m it rebounds to 1.20-1.40 m to the top of the ball: e 0.756-0.833 flown with the basketball preset's air;
        /// data/published/ball-rebound-rules.json), the board taken as rigid as the floor. The friction is a game value.
        /// </summary>
        public static readonly ContactProperties Board = new ContactProperties(0.8, 0.3);

        /// <summary>
        /// A tennis net across the court: two cord capsules sagging in straight lines from 1.07 m at the posts to 0.914 m at the
        /// centre (their tops), the mesh below them and the two posts, their centres 0.914 m outside the doubles sidelines (ITF
        /// Rules of Tennis, rule 1). The mesh follows the sagging cord in <see cref="TennisMeshPiecesPerHalf"/> rectangles a half,
        /// each reaching the cord's underside at its end nearer the centre: the gap left under the cord is at most 2.6 cm, less
        /// than a ball's diameter, so no ball passes between mesh and cord. Ids: firstId (cord, left half), +1 (cord, right
        /// half), +2 (every piece of the mesh), +3 and +4 (posts). The array holds the cords, the mesh pieces, then the posts.
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
            const int pieces = TennisMeshPiecesPerHalf;
            var shapes = new ContactShape[4 + 2 * pieces];
            shapes[0] = new CapsuleShape(firstId, leftTop, centreTop, r, NetCord);
            shapes[1] = new CapsuleShape(firstId + 1, centreTop, rightTop, r, NetCord);
            double rise = TennisCourt.NetHeightAtPostsMetres - TennisCourt.NetHeightAtCentreMetres;
            for (int k = 0; k < pieces; k++)
            {
                double inner = half * k / pieces, outer = half * (k + 1) / pieces;
                double height = TennisCourt.NetHeightAtCentreMetres - 2 * r + rise * (inner / half); // the cord's underside at the inner end
                for (int side = 0; side < 2; side++)
                {
                    double sign = side == 0 ? -1 : 1;
                    Vector3d centre = centreOnGround + a * (sign * (inner + outer) / 2) + u * (height / 2);
                    shapes[2 + 2 * k + side] = new NetMeshShape(firstId + 2, centre, n, a, outer - inner, height);
                }
            }

            Vector3d leftPost = centreOnGround - a * half, rightPost = centreOnGround + a * half;
            shapes[2 + 2 * pieces] = new CylinderShape(firstId + 3, leftPost, leftPost + u * TennisCourt.NetHeightAtPostsMetres, TennisPostRadiusMetres, Post);
            shapes[3 + 2 * pieces] = new CylinderShape(firstId + 4, rightPost, rightPost + u * TennisCourt.NetHeightAtPostsMetres, TennisPostRadiusMetres, Post);
            return shapes;
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
        /// A basketball hoop (FIBA): the ring, a torus whose top is 3.05 m up, with a 0.45 m inside diameter, its inside edge 0.15 m from the
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
            // FIBA's 3.05 m is the ring's upper edge: its tube's centre line is a tube radius below.
            Vector3d rimCentre = boardFootOnGround + u * (RimHeightMetres - tube) + n * (RimFromBoardMetres + ring - tube);
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
