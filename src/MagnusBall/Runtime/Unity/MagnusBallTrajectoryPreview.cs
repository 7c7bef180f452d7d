#nullable enable
using System;
using MagnusBall.Flight;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using UnityEngine;

namespace MagnusBall.Components
{
    /// <summary>
    /// Draws a ball's predicted path with a <see cref="LineRenderer"/>, from MagnusBall's
    /// <see cref="TrajectoryPredictor"/> with the same model, integrator, fixed step, events and contact shapes as a
    /// <see cref="MagnusBallFlight"/>, so the ball follows the line exactly (off a wall or the net cord too). It re-predicts only when the
    /// launch changes: a new launch or bounce of the followed flight (<see cref="MagnusBallFlight.ArcVersion"/>),
    /// or a different state given to <see cref="Show"/>. The points go to the line with one
    /// <c>SetPositions</c> from an array allocated once; a frame with nothing new allocates nothing.
    /// </summary>
    /// <remarks>
    /// Add it to a GameObject with a LineRenderer (it is required), drag the ball's MagnusBallFlight into
    /// <see cref="flight"/>. Before a launch, call <see cref="Show"/> with the launch you are aiming to see it;
    /// while the ball flies it shows the current arc (from the launch, then from each bounce) to the next
    /// touch of the ground.
    /// </remarks>
    [AddComponentMenu("MagnusBall/Trajectory Preview")]
    [RequireComponent(typeof(LineRenderer))]
    [HelpURL(UnityFrame.ManualUrl + "#trajectory-preview")]
    public class MagnusBallTrajectoryPreview : MonoBehaviour
    {
        /// <summary>The ball whose model is used and whose arcs are followed.</summary>
        [Tooltip("The ball: its model, integrator and fixed step are used for the prediction.")]
        public MagnusBallFlight? flight;

        /// <summary>Show the followed ball's current arc while it flies.</summary>
        [Tooltip("While the ball flies, show its current arc (from the launch or the latest bounce).")]
        public bool followFlight = true;

        /// <summary>
        /// Most points drawn (one per fixed step, plus the landing), read at Awake and at each inspector edit: an arc longer than this many fixed steps is
        /// drawn only to its last point (2048 points are 8.5 s at 1/240 s, 2 s at 1/1000 s).
        /// </summary>
        [Tooltip("Most points drawn (one per fixed step); a longer arc is cut short.")]
        [Min(2)]
        public int maxPoints = 2048;

        /// <summary>
        /// Longest prediction, s; finite and &gt; 0 (a prediction with another value throws once, when drawn; after mending it,
        /// call <see cref="Show"/> again, or the next launch or bounce redraws).
        /// </summary>
        [Tooltip("Longest prediction, s.")]
        [Min(0.01f)]
        public float maxDuration = 10f;

        private LineRenderer? _line;
        private TrajectoryPredictor? _predictor;
        private MagnusBall.Contact.Shapes.ContactShape[]? _predictorShapes;
        private Vector3d[] _path = Array.Empty<Vector3d>();
        private Vector3[] _points = Array.Empty<Vector3>();
        private FlightState _requested;
        private bool _hasRequest;
        private FlightState _drawn;
        private bool _hasDrawn;
        private int _followedVersion = -1;
        private FixedStepDriver? _followedDriver; // with the version: a new launch, or another ball, is a new arc

        /// <summary>How many times the path was predicted (a new launch, bounce or request each).</summary>
        public int Predictions { get; private set; }

        /// <summary>How many points the line has now.</summary>
        public int PointCount { get; private set; }

        /// <summary>
        /// Shows the path of a launch that has not happened yet (an aim); re-predicted at the next
        /// <c>LateUpdate</c> only if it differs from what is drawn.
        /// </summary>
        /// <param name="launch">The launch state (position m, velocity m/s, spin rad/s); finite.</param>
        /// <exception cref="ArgumentException">A component is not finite; nothing changes.</exception>
        public void Show(in FlightState launch)
        {
            if (!launch.IsFinite)
            {
                throw new ArgumentException($"launch must be finite; got {launch}.", nameof(launch));
            }

            _requested = launch;
            _hasRequest = true;
        }

        /// <summary>Clears the line and any requested launch.</summary>
        public void Clear()
        {
            _hasRequest = false;
            _hasDrawn = false;
            PointCount = 0;
            if (_line != null)
            {
                _line.positionCount = 0;
            }
        }

        private void Awake()
        {
            _line = GetComponent<LineRenderer>();
            _line.useWorldSpace = true;
            _line.positionCount = 0; // a new LineRenderer has two points, (0, 0, 0) and (0, 0, 1): draw nothing yet
            int n = Math.Max(2, maxPoints);
            _path = new Vector3d[n];
            _points = new Vector3[n];
        }

        /// <summary>
        /// Unity calls this after an inspector edit (also during Play): the line is predicted again at the next
        /// <c>LateUpdate</c> with the new <see cref="maxDuration"/> and <see cref="maxPoints"/> (once the component is awake).
        /// </summary>
        private void OnValidate()
        {
            if (_line == null)
            {
                return; // not awake yet: Awake reads the fields
            }

            int n = Math.Max(2, maxPoints);
            if (n != _path.Length)
            {
                _path = new Vector3d[n];
                _points = new Vector3[n];
            }

            if (_hasDrawn)
            {
                _followedVersion = -1; // the followed arc is drawn again
                _hasDrawn = false; // and so is a requested launch
            }
        }

        private void LateUpdate()
        {
            if (flight == null || _line == null)
            {
                return;
            }

            if (followFlight && flight.Driver == null && _followedDriver != null)
            {
                // The followed flight was cancelled: its arc is not drawn on.
                _followedDriver = null;
                Clear();
            }
            else if (followFlight && flight.Driver != null && (flight.ArcVersion != _followedVersion || flight.Driver != _followedDriver))
            {
                _followedVersion = flight.ArcVersion;
                _followedDriver = flight.Driver;
                _hasRequest = false;
                Draw(flight.ArcStart);
            }
            else if (_hasRequest && !(_hasDrawn && Same(_requested, _drawn)))
            {
                Draw(_requested);
            }
        }

        private void Draw(in FlightState from)
        {
            // Marked drawn first: a prediction the settings refuse (maxDuration 0, a ball's bad inspector values) throws once
            // for this launch or arc, not again every frame.
            _drawn = from;
            _hasDrawn = true;
            _line!.positionCount = 0;
            PointCount = 0;
            MagnusBallFlight ball = flight!;
            if (_predictor == null || _predictor.Model != ball.Model || _predictor.Integrator != ball.Integrator ||
                _predictor.Step != ball.FixedStep || _predictor.Events != ball.EventSet || _predictorShapes != ball.Shapes)
            {
                _predictor = new TrajectoryPredictor(ball.Model, ball.Integrator, ball.FixedStep, ball.EventSet, ball.Shapes);
                _predictorShapes = ball.Shapes;
            }

            int count = _predictor.Predict(from, maxDuration, _path).SampleCount;
            for (int i = 0; i < count; i++)
            {
                _points[i] = UnityFrame.ToUnity(_path[i]);
            }

            _line!.positionCount = count;
            _line.SetPositions(_points); // Unity uses the first positionCount points
            PointCount = count;
            Predictions++;
        }

        private static bool Same(in FlightState a, in FlightState b) =>
            a.Position.Equals(b.Position) && a.Velocity.Equals(b.Velocity) && a.AngularVelocity.Equals(b.AngularVelocity);
    }
}
