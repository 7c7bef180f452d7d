#nullable enable
namespace MagnusBall.Samples.TennisScene
{
    /// <summary>
    /// The scene's six shots, all hit by a right-handed player from the near side of the court (x &lt; 0)
    /// toward the far side. Speeds and spins are typical of the professional game (serves 40-55 m/s and
    /// 1000-4000 rpm, rally shots 20-35 m/s and up to about 3000 rpm; Cross &amp; Lindsey 2005, Brody et al.
    /// 2002); the launch angles were chosen here so each shot clears the net and lands in.
    /// </summary>
    public static class StandardShots
    {
        /// <summary>A flat first serve from the deuce side into the far deuce box: fast, little spin.</summary>
        public static TennisShot FlatServe => new TennisShot(
            "flat serve", new Vector3d(-TennisCourt.HalfLength - 0.1, TennisCourt.ServeHeight, -0.8),
            50, -5.3, 9.0, 800, 0, TargetArea.FarDeuceServiceBox);

        /// <summary>A kick (topspin) second serve: slower, hit upward, heavy topspin with some sidespin.</summary>
        public static TennisShot KickServe => new TennisShot(
            "kick serve", new Vector3d(-TennisCourt.HalfLength - 0.1, TennisCourt.ServeHeight, -0.8),
            38, -0.5, 12.0, 3500, -1000, TargetArea.FarDeuceServiceBox);

        /// <summary>A topspin forehand cross-court from behind the baseline.</summary>
        public static TennisShot TopspinForehand => new TennisShot(
            "topspin forehand", new Vector3d(-TennisCourt.HalfLength - 1.0, 1.0, -2.5),
            32, 12.0, 14.0, 2500, 0, TargetArea.FarSinglesCourt);

        /// <summary>A sliced backhand down the line: backspin keeps it low and floating.</summary>
        public static TennisShot SliceBackhand => new TennisShot(
            "slice backhand", new Vector3d(-TennisCourt.HalfLength - 0.5, 0.9, 3.0),
            24, 8.0, -1.0, -2000, 0, TargetArea.FarSinglesCourt);

        /// <summary>A topspin lob over a player at the net.</summary>
        public static TennisShot Lob => new TennisShot(
            "topspin lob", new Vector3d(-TennisCourt.HalfLength - 0.5, 1.0, 0.0),
            22, 26.0, 2.0, 1800, 0, TargetArea.FarSinglesCourt);

        /// <summary>A backspin drop shot from inside the court, landing just over the net.</summary>
        public static TennisShot DropShot => new TennisShot(
            "drop shot", new Vector3d(-5.0, 0.9, -1.0),
            11, 17.0, 5.0, -2500, 0, TargetArea.FarSinglesCourt);

        /// <summary>
        /// A net-cord let: a flat serve at 40 m/s down the middle, hit 0.5 degree lower than one that clears, so that it clips the tape (the scene's net is the library's
        /// contact shapes, MagnusBall.Shots.SportShapes.TennisNet) and drops in the service box. Not one of the six
        /// (<see cref="All"/>): the headless runner flies it after them.
        /// </summary>
        public static TennisShot NetCordLet => new TennisShot(
            "net-cord let", new Vector3d(-TennisCourt.HalfLength - 0.1, TennisCourt.ServeHeight, 0.5),
            40, -5.79, 2.0, 800, 0, TargetArea.FarDeuceServiceBox);

        /// <summary>All six, in the order of the table.</summary>
        public static TennisShot[] All() => new[] { FlatServe, KickServe, TopspinForehand, SliceBackhand, Lob, DropShot };
    }
}
