using System;
using MagnusBall.Samples.TennisScene;
using NUnit.Framework;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// The scene's shots defined by racket swings (Shared/TennisSwing, StandardSwings) and the library's inverse
    /// (SwingAim through ShotSimulation.AimSwing): swings found for the six standard shots land where the shots land today.
    /// </summary>
    [TestFixture]
    public class SwingShotTests
    {
        private static readonly ShotSimulation Simulation = new ShotSimulation(new SceneSettings());

        public static string[] Names => Array.ConvertAll(StandardShots.All(), s => s.Name);

        [TestCaseSource(nameof(Names))]
        public void TheInverse_FindsASwing_ThatLandsWhereTheShotLandsToday(string name)
        {
            TennisShot shot = Array.Find(StandardShots.All(), s => s.Name == name)!;
            TennisSwing start = Array.Find(StandardSwings.All(), s => s.Name == name)!;
            ShotReport today = Simulation.Run(shot, Span<MagnusBall.Vector3d>.Empty);

            // Start the inverse away from the stored answer: face 3 deg more open, azimuth 2 deg off.
            var guess = start.WithSwing(start.Swing.WithFace(start.Swing.FaceTiltDegrees + 3, start.Swing.AzimuthDegrees + 2));
            // The aim solver takes the lowest elevation that reaches a point: from 8 deg below the shot's own elevation,
            // so a lob is not solved as a drive.
            TennisSwing? solved = Simulation.AimSwing(guess, today.Landing.X, today.Landing.Z, shot.ElevationDegrees - 8);
            Assert.That(solved, Is.Not.Null, $"{name}: no swing found");
            ShotReport bySwing = Simulation.Run(solved!.ToShot(Simulation.Settings.Ball), Span<MagnusBall.Vector3d>.Empty);
            double miss = MagnusBall.Vector3d.Distance(bySwing.Landing, today.Landing);
            TestContext.Out.WriteLine($"{name}: {solved.Describe()} -> miss {miss:E2} m");
            // The aim solver refines angles to 1e-8 rad and the swing's direction matches it to 1e-9 rad: over 10-20 m of
            // flight that is ~2e-7 m. 1e-5 m leaves a factor 50 for the different step paths (driver vs solver).
            Assert.That(miss, Is.LessThan(1e-5));
            Assert.That(bySwing.IsIn, Is.EqualTo(today.IsIn));
            Assert.That(solved.Swing.Speed, Is.EqualTo(start.Swing.Speed), "the player's racket speed is kept");
            Assert.That(solved.Swing.PathElevationDegrees, Is.EqualTo(start.Swing.PathElevationDegrees), "the player's path is kept");
        }

        [TestCaseSource(nameof(Names))]
        public void TheStoredSwings_LandWhereTheShotsLand(string name)
        {
            // StandardSwings stores the inverse's face tilt and azimuth rounded to 0.001 deg: 1.7e-5 rad over up to 20 m
            // of flight, a few times 0.1 mm; 5 mm allows for the spin and speed change the rounding also makes.
            TennisShot shot = Array.Find(StandardShots.All(), s => s.Name == name)!;
            TennisSwing swing = Array.Find(StandardSwings.All(), s => s.Name == name)!;
            ShotReport today = Simulation.Run(shot, Span<MagnusBall.Vector3d>.Empty);
            ShotReport bySwing = Simulation.Run(swing.ToShot(Simulation.Settings.Ball), Span<MagnusBall.Vector3d>.Empty);
            Assert.That(MagnusBall.Vector3d.Distance(bySwing.Landing, today.Landing), Is.LessThan(5e-3));
            Assert.That(bySwing.IsIn, Is.True);
            Assert.That(bySwing.Shot.Swing, Is.SameAs(swing));
        }

        [Test]
        public void AShotFromALaunch_KeepsItsExactVelocityAndSpin()
        {
            var v = new MagnusBall.Vector3d(30, 4, -2);
            var w = new MagnusBall.Vector3d(10, -20, 150); // includes a part about the direction of flight
            TennisShot shot = TennisShot.FromLaunch("x", new MagnusBall.Vector3d(-12, 1, 0), v, w, TargetArea.FarSinglesCourt);
            Assert.That(shot.Velocity, Is.EqualTo(v));
            Assert.That(shot.AngularVelocity, Is.EqualTo(w));
            Assert.That(shot.Speed, Is.EqualTo(v.Length));
        }
    }
}
