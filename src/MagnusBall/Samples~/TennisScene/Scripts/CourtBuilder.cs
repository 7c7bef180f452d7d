using MagnusBall;
using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Unity
{
    /// <summary>
    /// Builds the court from primitives at Start, to the ITF dimensions in <see cref="TennisCourt"/>: the
    /// surface, every line, the net (0.914 m at the centre strap rising to 1.07 m at the posts) and the posts.
    /// The court lies in the x-z plane with the net along z at x = 0 (the thesis's axes: x into the screen,
    /// y up, z to the left).
    /// </summary>
    public class CourtBuilder : MonoBehaviour
    {
        public Color surfaceColor = new Color(0.24f, 0.45f, 0.30f, 1f);
        public Color runoffColor = new Color(0.30f, 0.52f, 0.36f, 1f);
        public Color lineColor = Color.white;
        public Color netColor = new Color(0.1f, 0.1f, 0.1f, 1f);
        [Tooltip("Vertical slices of the net, to follow the cord from the posts down to the centre strap.")]
        public int netSegments = 16;

        private const float LineThickness = 0.002f; // lines stand 2 mm proud of the surface so they draw on top

        private void Start() => Build();

        /// <summary>Creates the court's objects under this transform.</summary>
        [ContextMenu("Build court")]
        public void Build()
        {
            Box("runoff", new Vector3d(0, -0.011, 0), new Vector3d(TennisCourt.Length + 12, 0.02, TennisCourt.DoublesWidth + 8), runoffColor);
            Box("court", new Vector3d(0, -0.005, 0), new Vector3d(TennisCourt.Length, 0.01, TennisCourt.DoublesWidth), surfaceColor);

            foreach (CourtLine line in TennisCourt.Lines())
            {
                // Each line is drawn inside the court's outline: the dimensions are to the lines' outer edges.
                Vector3d along = line.End - line.Start;
                double length = along.Length;
                Vector3d middle = (line.Start + line.End) * 0.5;
                Vector3d inward = new Vector3d(-System.Math.Sign(middle.X), 0, -System.Math.Sign(middle.Z)) * (TennisCourt.LineWidth / 2);
                bool runsAlongX = System.Math.Abs(along.X) > System.Math.Abs(along.Z);
                Vector3d centre = middle + (runsAlongX ? new Vector3d(0, 0, inward.Z) : new Vector3d(inward.X, 0, 0));
                Vector3d size = runsAlongX
                    ? new Vector3d(length, LineThickness, TennisCourt.LineWidth)
                    : new Vector3d(TennisCourt.LineWidth, LineThickness, length);
                Box(line.Name, centre + TennisCourt.Up * (LineThickness / 2), size, lineColor);
            }

            double half = TennisCourt.PostOffset;
            double width = 2 * half / netSegments;
            for (int i = 0; i < netSegments; i++)
            {
                double z = -half + (i + 0.5) * width;
                double height = TennisCourt.NetHeightAt(z);
                Box("net", new Vector3d(0, height / 2, z), new Vector3d(0.02, height, width), netColor);
            }

            foreach (double z in new[] { -half, half })
            {
                GameObject post = GameObject.CreatePrimitive(PrimitiveType.Cylinder);
                post.name = "net post";
                post.transform.SetParent(transform, false);
                // A Unity cylinder is 2 units tall: scale y by half the height.
                post.transform.localPosition = UnityFrame.ToUnity(new Vector3d(0, TennisCourt.NetHeightAtPosts / 2, z));
                post.transform.localScale = new Vector3(0.08f, (float)(TennisCourt.NetHeightAtPosts / 2), 0.08f);
                post.GetComponent<Renderer>().material.color = netColor;
            }
        }

        private void Box(string name, Vector3d centre, Vector3d size, Color color)
        {
            GameObject box = GameObject.CreatePrimitive(PrimitiveType.Cube);
            box.name = name;
            box.transform.SetParent(transform, false);
            box.transform.localPosition = UnityFrame.ToUnity(centre);
            box.transform.localScale = UnityFrame.ToUnity(size);
            box.GetComponent<Renderer>().material.color = color;
        }
    }
}
