# segmat_batch: the batch runner (tools/segmat_batch).
